#!/usr/bin/env bash
# Measures the simulator's real-time factor: benchmarks/sim.sh [--step-ms s] [n...]
#
#   n          numbers of atoms (default: 1 10 100 1000), each a grid of free atoms in tripod pose
#              whose controllers read their sensors and swing their upper legs every 10 ms cycle
#   --step-ms  the physics step in milliseconds (default 1)
#   --legs l   the atoms' leg model: kinematic (default) or jointed (docs/simulator.md)
#   --threads t  the threads a step's work on the atoms is spread over (default 1)
#   --warmup-seconds w, --seconds m   warm up w seconds of real time (default 2), then measure
#              for m seconds of real time (default 3; at least one control cycle)
#   --no-build use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs each size in a JVM of
# its own on a JDK >= 21 (scripts/java.sh) with
# SIM_JAVA_OPTS (default "-Xms1g -Xmx1g"). Prints one line per size:
#   sim name=rtf atoms=<n> step_ms=<s> rtf=<x> legs=<l> threads=<t> cpu_rtf=<y> us_per_atom_step=<z> load=<a>
# rtf is virtual seconds simulated per real second, cpu_rtf per second of the simulating threads'
# CPU time, us_per_atom_step that CPU time per atom and physics step, and load the machine's
# one-minute load average when the size finished (see docs/simulator.md, "Speed").
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
jar="$here/target/benchmarks.jar"

sizes=()
args=()
build=1
while (($#)); do
  case "$1" in
    --step-ms) args+=(--step-ms "${2:?--step-ms needs a number}"); shift 2 ;;
    --warmup-seconds) args+=(--warmup-seconds "${2:?--warmup-seconds needs a number}"); shift 2 ;;
    --legs) args+=(--legs "${2:?--legs needs kinematic or jointed}"); shift 2 ;;
    --threads) args+=(--threads "${2:?--threads needs a number}"); shift 2 ;;
    --seconds) args+=(--seconds "${2:?--seconds needs a number}"); shift 2 ;;
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    -*) echo "sim.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) sizes+=("$1"); shift ;;
  esac
done
if ((${#sizes[@]} == 0)); then
  sizes=(1 10 100 1000)
fi

# shellcheck source=../scripts/java.sh
source "$root/scripts/java.sh"
java="$(find_java sim.sh)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "sim.sh: $jar is missing; run without --no-build" >&2; exit 1; }

read -r -a opts <<<"${SIM_JAVA_OPTS:--Xms1g -Xmx1g}"
echo "# $("$java" -version 2>&1 | head -1); options: ${opts[*]}; $(nproc) cores" >&2
for n in "${sizes[@]}"; do
  line="$("$java" "${opts[@]}" -cp "$jar" org.armgals.bench.sim.SimRtf "${args[@]}" "$n")"
  echo "$line load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo unknown)"
done
