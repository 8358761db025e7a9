#!/usr/bin/env bash
# Runs the GALS and MAAM benchmarks: benchmarks/gals.sh [--seconds s] [--no-build] [name...]
#
#   name        reschedule cycle-overhead island-overhead jitter (default: all); each prints:
#                 gals name=reschedule modules=<n> ms=<x>       n = 1,000, 10,000, 100,000
#                 gals name=cycle-overhead ratio=<x> min=<a> max=<b> rounds=<n> robot_ns=<r> loop_ns=<l>
#                   (a MAAM robot's cycle stepped by hand, no island, / a hand-written loop; CPU)
#                 gals name=island-overhead robots=10 cpu_ratio=<x> min=<a> max=<b> wall_ratio=<w>
#                   island_cpu_us=<i> hand_cpu_us=<h>  (robots on an island / by hand; process CPU)
#                 gals name=jitter impl=<armgals|raw> hz=1000 p50_us=<a> p99_us=<b> max_us=<c>
#   --seconds   how long each measured part of jitter runs (default 5; warmed up as long again)
#   --no-build  use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs the entry point
# org.armgals.bench.gals.Gals with the names given, in one JVM, on a JDK >= 21 (scripts/java.sh),
# with GALS_JAVA_OPTS (default "-Xms1g -Xmx1g"; -Dgals.workers=n sets the island runtime's
# workers, default one per core). Result lines go to standard output, details to standard error
# (docs/maam-guide.md "Measuring", docs/gals-guide.md). Measure on a quiet machine.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
jar="$here/target/benchmarks.jar"

seconds=5
build=1
names=()
while (($#)); do
  case "$1" in
    --seconds) seconds="${2:?--seconds needs a count}"; shift 2 ;;
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    -*) echo "gals.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done

# shellcheck source=../scripts/java.sh
source "$root/scripts/java.sh"
java="$(find_java gals.sh)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "gals.sh: $jar is missing; run without --no-build" >&2; exit 1; }

read -r -a opts <<<"${GALS_JAVA_OPTS:--Xms1g -Xmx1g}"
echo "# $("$java" -version 2>&1 | head -1); options: ${opts[*]}; $(nproc) cores" >&2
"$java" "${opts[@]}" "-Dgals.seconds=$seconds" -cp "$jar" org.armgals.bench.gals.Gals "${names[@]}"
