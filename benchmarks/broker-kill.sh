#!/usr/bin/env bash
# Runs the broker kill test and prints its figures: benchmarks/broker-kill.sh [--runs n]
#
#   --runs n  how many times (default 1)
#
# Each run is the brokers module's BrokerKillTest through the Maven wrapper: a standalone Artemis
# broker (a process of its own on 127.0.0.1, login required) killed with SIGKILL and started again
# while runtime a sends runtime b an event every 0.5 ms and a request every 50 events, once at
# most once (a broker without a journal) and once at least once (a broker with a journal). The
# test asserts the invariants (docs/benchmarks-broker.md); this script prints its two lines:
#   kill-test guarantee=<amo|alo> calls=<n> sent=<n> unsent=<n> received=<n> lost=<n>
#     duplicates=<n> rejected=<n> asks=<n> answered=<n> outage_ms=<n> longest_call_us=<n>
# (one line each), and exits non-zero if the test fails.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
runs=1
while (($#)); do
  case "$1" in
    --runs) runs="${2:?--runs needs a count}"; shift 2 ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    *) echo "broker-kill.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "broker-kill.sh: --runs must be >= 1, was '$runs'" >&2; exit 2; }

report="$root/brokers/target/surefire-reports/org.armgals.brokers.BrokerKillTest-output.txt"
for ((i = 1; i <= runs; i++)); do
  echo "# run $i of $runs; $(uptime)" >&2
  (cd "$root" && ./mvnw -B -q -pl brokers -am verify -Dtest=BrokerKillTest \
    -Dsurefire.failIfNoSpecifiedTests=false) >&2
  grep -h '^kill-test ' "$report"
done
