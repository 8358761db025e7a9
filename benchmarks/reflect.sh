#!/usr/bin/env bash
# The reflective loop's figures: benchmarks/reflect.sh [--runs n] [--seconds s] [--missed-seconds s]
#                                [--warmup-seconds s] [--rounds n] [--cycles n] [--no-build] [name...]
#
#   name   notify-cost latency missed (default: all); each prints, details on stderr:
#            reflect name=notify-cost pacing=<lockstep|free|realtime> atoms=4 cost_ns=<c>
#              share_pct=<c / 10 ms> min_ns max_ns threads_cost_ns off_sim_thread_cost_ns
#              with_ns without_ns rounds cycles load=<at start>-<at end>
#              (process CPU per cycle of the 4-atom caterpillar, its head notifying its meta every
#              cycle, minus the same robots notifying no one; median of paired rounds)
#            reflect name=latency-run meta=<local|remote> hz=100 seconds requests applied
#              p50_cycles p99_cycles max_cycles p50_us p99_us missed overruns load   (each run)
#            reflect name=latency meta=<local|remote> hz=100 runs requests p50_cycles
#              p99_cycles (min-max) p50_us p99_us (min-max) load   (medians over the runs)
#              (the benchmark's example reflect-asking, free at 100 Hz: notified to applied)
#            reflect name=missed-run robot=caterpillar meta=remote hz=100 seconds warmup_s missed
#              overruns requests load   (each run, in a JVM of its own, as ./armgals run
#              caterpillar --realtime --meta remote --seconds s --warmup-seconds w would)
#            reflect name=missed ... warmup_s runs missed=<median> (min-max) load
#   --runs            runs of latency (each meta place) and of missed (default 3)
#   --seconds         length of a latency run, simulated = real seconds (default 30)
#   --missed-seconds  length of a missed run (default 60)
#   --warmup-seconds  simulated seconds each missed run warms up first, thrown away, as ./armgals run
#                     does before a paced run (default 5, as there; 0 for none)
#   --rounds, --cycles  notify-cost's measured rounds per pacing (default 5) and cycles per round
#                     (default 3000; realtime rounds take at most 500)
#   --no-build        use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs the entry point
# org.armgals.bench.reflect.Reflect on a JDK >= 21 (scripts/java.sh) with ZGC, as ./armgals runs,
# and REFLECT_JAVA_OPTS (a collector named there is taken instead), the runs' outputs (trace,
# pictures, loop.jsonl) under benchmarks/target/reflect/. `uptime` goes to stderr before each figure. See
# docs/benchmarks-reflection.md. Measure on a quiet machine.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
jar="$here/target/benchmarks.jar"

runs=3
build=1
args=()
names=()
while (($#)); do
  case "$1" in
    --runs) runs="${2:?--runs needs a count}"; shift 2 ;;
    --seconds | --missed-seconds | --warmup-seconds | --rounds | --cycles)
      args+=("$1" "${2:?$1 needs a value}"); shift 2 ;;
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    notify-cost | latency | missed) names+=("$1"); shift ;;
    *) echo "reflect.sh: unknown option or name '$1' (try --help)" >&2; exit 2 ;;
  esac
done
if ((${#names[@]} == 0)); then
  names=(notify-cost latency missed)
fi

# shellcheck source=../scripts/java.sh
source "$root/scripts/java.sh"
java="$(find_java reflect.sh)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "reflect.sh: $jar is missing; run without --no-build" >&2; exit 1; }

# The JVM's options as ./armgals gives them (scripts/java.sh), then REFLECT_JAVA_OPTS.
read -r -a jvm <<<"$(armgals_jvm_options "$java" "${REFLECT_JAVA_OPTS:-}")"
read -r -a opts <<<"${REFLECT_JAVA_OPTS:-}"
out="$here/target/reflect"
reflect() {
  "$java" "${jvm[@]}" "${opts[@]}" -cp "$jar" org.armgals.bench.reflect.Reflect \
    --out "$out" "${args[@]}" "$@"
}
echo "# $("$java" -version 2>&1 | head -1); options: ${jvm[*]} ${opts[*]:-}; $(nproc) cores" >&2
for name in "${names[@]}"; do
  echo "# $name: $(uptime)" >&2
  case "$name" in
    missed) # a JVM of its own for each run, as ./armgals run would
      missed=()
      seconds=""
      warmup=""
      for ((i = 0; i < runs; i++)); do
        line="$(reflect --runs 1 missed | grep '^reflect name=missed-run')"
        echo "$line"
        missed+=("$(sed -n 's/.* missed=\([0-9]*\).*/\1/p' <<<"$line")")
        seconds="$(sed -n 's/.* seconds=\([^ ]*\).*/\1/p' <<<"$line")"
        warmup="$(sed -n 's/.* warmup_s=\([^ ]*\).*/\1/p' <<<"$line")"
      done
      mapfile -t sorted < <(printf '%s\n' "${missed[@]}" | sort -n)
      n=${#sorted[@]}
      echo "reflect name=missed robot=caterpillar meta=remote hz=100 seconds=$seconds" \
        "warmup_s=$warmup runs=$n" \
        "missed=${sorted[$(((n - 1) / 2))]} (${sorted[0]}-${sorted[$((n - 1))]})" \
        "load=$(cut -d' ' -f1 /proc/loadavg)"
      ;;
    *) reflect --runs "$runs" "$name" ;;
  esac
done
