#!/usr/bin/env bash
# Runs the broker benchmark: benchmarks/broker.sh [--warmup n] [--runs n] [--messages n]
#                                                 [--requests n] [--guarantee amo|alo|both]
#                                                 [--no-build] [name...]
#
#   name        events futurertt (default: both)
#   --warmup n  warm-up rounds, printed with a "warmup" prefix (default 2); --runs n  measured
#               rounds (default 3)
#   --messages n  events per events run (default 200000); --requests n  round trips per
#               futurertt run (default 20000)
#   --guarantee g  amo (at most once), alo (at least once, a hundredth of the messages and requests)
#               or both (default)
#   --no-build  use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs, in one JVM over two
# embedded Artemis brokers (one without a journal for amo, one with a journal for alo; each with an
# in-VM acceptor and a netty acceptor on 127.0.0.1 that requires its login), rounds of every
# workload with each guarantee on each transport (invm, netty) with each implementation (raw
# Jakarta JMS; armgals: two runtimes, each with its own JmsTransport), interleaved so that all see
# much the same load.
# Uses a JDK >= 21 (scripts/java.sh) with the options
# in BROKER_JAVA_OPTS, default "-Xms1g -Xmx1g". Prints one line per run (docs/benchmarks-broker.md):
#   broker name=events impl=<raw|armgals> transport=<invm|netty> guarantee=<amo|alo> ops_per_s=<x>
#   broker name=futurertt impl=<raw|armgals> transport=<invm|netty> guarantee=<amo|alo> p50_us=<x> p99_us=<y>
# and exits non-zero if a run fails.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
jar="$here/target/benchmarks.jar"

args=()
build=1
while (($#)); do
  case "$1" in
    --warmup | --runs | --messages | --requests | --guarantee)
      args+=("$1" "${2:?$1 needs a count}")
      shift 2 ;;
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    -*) echo "broker.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) args+=("$1"); shift ;;
  esac
done

# shellcheck source=../scripts/java.sh
source "$root/scripts/java.sh"
java="$(find_java broker.sh)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "broker.sh: $jar is missing; run without --no-build" >&2; exit 1; }

read -r -a opts <<<"${BROKER_JAVA_OPTS:--Xms1g -Xmx1g}"
if (($(jdk_major "$(dirname "$(dirname "$java")")") >= 23)); then
  # Netty (inside Artemis) still uses sun.misc.Unsafe; say it is allowed, as it is by default,
  # without the warning.
  opts+=(--sun-misc-unsafe-memory-access=allow)
fi
if (($(jdk_major "$(dirname "$(dirname "$java")")") >= 22)); then
  # Artemis loads its native journal library at start-up (unused here): allowed, without the warning.
  opts+=(--enable-native-access=ALL-UNNAMED)
fi
echo "# $("$java" -version 2>&1 | head -1); options: ${opts[*]}; $(nproc) cores" >&2
exec "$java" "${opts[@]}" -cp "$jar" org.armgals.bench.broker.BrokerBench "${args[@]}"
