#!/usr/bin/env bash
# Runs the statecharts against a public conformance suite: benchmarks/scxml-conformance.sh
#                                                            [--no-build] [test-directory]
#
#   test-directory  the test/ directory of the SCION test framework (Apache 2.0), 335 charts with
#                   their event scripts, the W3C implementation report tests among them; default:
#                   benchmarks/target/scxml-suite/package/test, fetched there with
#                   `npm pack @scion-scxml/test-framework@2.0.16` if it is missing
#   --no-build      use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs
# org.armgals.bench.scxml.ScxmlConformance on a JDK >= 21 (scripts/java.sh). Prints one line per
# chart (scxml chart=<file> result=pass|pass-queued|fail|refused|no-script [:: detail]), then
#   scxml charts=<n> pass=<a> pass-queued=<b> fail=<c> refused=<d> no-script=<e> roundtrip-fail=<f>
#   scxml refused=<n> :: <what the refusals name>   (one line per kind, most first)
# (docs/representations.md, "Conformance"). Exits non-zero if a chart fails or does not
# round-trip.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
jar="$here/target/benchmarks.jar"

build=1
suite=""
while (($#)); do
  case "$1" in
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    -*) echo "scxml-conformance.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) suite="$1"; shift ;;
  esac
done

if [[ -z "$suite" ]]; then
  suite="$here/target/scxml-suite/package/test"
  if [[ ! -d "$suite" ]]; then
    command -v npm >/dev/null || {
      echo "scxml-conformance.sh: npm is needed to fetch the suite; or give its test directory" >&2
      exit 1
    }
    mkdir -p "$here/target/scxml-suite"
    (cd "$here/target/scxml-suite" &&
      npm pack --silent @scion-scxml/test-framework@2.0.16 >/dev/null &&
      tar -xzf scion-scxml-test-framework-2.0.16.tgz)
  fi
fi
[[ -d "$suite" ]] || { echo "scxml-conformance.sh: '$suite' is not a directory" >&2; exit 2; }

# shellcheck source=../scripts/java.sh
source "$root/scripts/java.sh"
java="$(find_java scxml-conformance.sh)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "scxml-conformance.sh: $jar is missing; run without --no-build" >&2; exit 1; }

"$java" -cp "$jar" org.armgals.bench.scxml.ScxmlConformance "$suite"
