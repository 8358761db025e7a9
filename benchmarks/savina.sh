#!/usr/bin/env bash
# Runs the Savina-style suite: benchmarks/savina.sh [--impl armgals|pekko|yardstick|both|all]
#                                                   [name...]
#   name       pingpong counting threadring fjthrput creation futurertt mem (default: all)
#   --impl     which implementation(s) to run; default armgals; both = armgals and pekko,
#              all = armgals, pekko and yardstick (hand-written actors on a fork-join pool)
#   --warmup n, --warmup-seconds s   warm up each workload by at least n runs (default 2) and
#              s seconds (default 5); --runs n   measured runs (default 3)
#   --cpus l   run each JVM on the CPUs in list l only (taskset -c l, e.g. 0 or 0,1); the
#              runtimes size their thread pools from the CPUs the JVM sees
#   --no-build use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs each workload of each
# implementation in a JVM of its own, the implementations of a workload back to back, on a JDK
# >= 21 (JAVA_HOME if it is one, else the newest under /usr/lib/jvm) with the same JVM options
# for all: SAVINA_JAVA_OPTS, default "-Xms4g -Xmx4g". Sizes are overridden with
# -Dsavina.<key>=<n> in SAVINA_JAVA_OPTS (see Sizes.java). Prints one line per run (see
# docs/benchmarks.md); exits non-zero if a run fails its check. Before each workload, unless
# --cpus names one CPU, it prints what moving a cache line between two cores costs at that moment
# (LineRoundTrip, "line median_round_trip_ns=<ns> rounds=3"): on a shared virtual machine that
# cost changes from hour to hour, and with it every workload that hands messages between cores.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
jar="$here/target/benchmarks.jar"

impls=(armgals)
names=()
warmup=2
warmup_seconds=5
runs=3
build=1
cpus=""
while (($#)); do
  case "$1" in
    --impl)
      case "${2:-}" in
        armgals | pekko | yardstick) impls=("$2") ;;
        both) impls=(armgals pekko) ;;
        all) impls=(armgals pekko yardstick) ;;
        *)
          echo "savina.sh: --impl takes armgals, pekko, yardstick, both or all, not '${2:-}'" >&2
          exit 2 ;;
      esac
      shift 2 ;;
    --warmup) warmup="${2:?--warmup needs a count}"; shift 2 ;;
    --warmup-seconds) warmup_seconds="${2:?--warmup-seconds needs a count}"; shift 2 ;;
    --runs) runs="${2:?--runs needs a count}"; shift 2 ;;
    --cpus)
      cpus="${2:-}"
      if [[ ! "$cpus" =~ ^[0-9]+([-,][0-9]+)*$ ]]; then
        echo "savina.sh: --cpus takes a CPU list such as 0 or 0,1 or 0-1, not '$cpus'" >&2
        exit 2
      fi
      shift 2 ;;
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    -*) echo "savina.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
if ((${#names[@]} == 0)); then
  names=(pingpong counting threadring fjthrput creation futurertt mem)
fi

# shellcheck source=../scripts/java.sh
source "$root/scripts/java.sh"
java="$(find_java savina.sh)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "savina.sh: $jar is missing; run without --no-build" >&2; exit 1; }

read -r -a opts <<<"${SAVINA_JAVA_OPTS:--Xms4g -Xmx4g}"
if (($(jdk_major "$(dirname "$(dirname "$java")")") >= 23)); then
  # Pekko still uses sun.misc.Unsafe; say it is allowed, as it is by default, without the warning.
  opts+=(--sun-misc-unsafe-memory-access=allow)
fi
pin=()
if [[ -n "$cpus" ]]; then
  command -v taskset >/dev/null || { echo "savina.sh: --cpus needs taskset (util-linux)" >&2; exit 1; }
  pin=(taskset -c "$cpus")
fi
echo "# $("$java" -version 2>&1 | head -1); options: ${opts[*]}; $(nproc) cores${cpus:+, on CPUs $cpus}" >&2
# Workload outside, implementation inside: on a shared, noisy machine the implementations of
# one workload then run minutes apart at most, under much the same load.
probe=1
if [[ "$cpus" =~ ^[0-9]+$ ]]; then
  probe=0 # one CPU: a round trip would wait for the scheduler, not for a line
fi
for name in "${names[@]}"; do
  if ((probe)); then
    "${pin[@]}" "$java" -cp "$jar" org.armgals.bench.savina.LineRoundTrip --rounds 3 \
      --trips 200000 | grep '^line median'
  fi
  for impl in "${impls[@]}"; do
    "${pin[@]}" "$java" "${opts[@]}" -cp "$jar" org.armgals.bench.savina.Savina \
      --impl "$impl" --warmup "$warmup" --warmup-seconds "$warmup_seconds" --runs "$runs" "$name"
  done
done
