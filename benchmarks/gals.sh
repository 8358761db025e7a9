#!/usr/bin/env bash
# Runs the GALS benchmarks: benchmarks/gals.sh [--seconds s] [--no-build] [name...]
#
#   name       jitter (default: every benchmark the entry point knows)
#   --seconds  how long each measured part runs (default 5; each is warmed up as long again)
#   --no-build use benchmarks/target/benchmarks.jar as it is
#
# Builds benchmarks/target/benchmarks.jar with the Maven wrapper, then runs the named benchmarks
# in one JVM (org.armgals.bench.gals.Gals, one entry point with named benchmarks; a new one is
# registered there) on a JDK >= 21 (JAVA_HOME if it is one, else the newest under /usr/lib/jvm),
# with GALS_JAVA_OPTS (default "-Xms1g -Xmx1g"; -Dgals.workers=n sets the island runtime's
# workers, default one per core). Prints one line per measurement (the island's full figures go
# to standard error):
#   gals name=jitter impl=<armgals|raw> hz=1000 p50_us=<a> p99_us=<b> max_us=<c>
# (see docs/gals-guide.md). Measure on a quiet machine: jitter is what other load does to us.
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
    -h | --help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "gals.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done

# The major version of the JDK at $1, or nothing if it is not a JDK.
jdk_major() {
  local home="$1" version=""
  [[ -x "$home/bin/java" ]] || return 0
  if [[ -f "$home/release" ]]; then
    version="$(sed -n 's/^JAVA_VERSION="\(.*\)"/\1/p' "$home/release")"
  fi
  if [[ -z "$version" ]]; then
    version="$("$home/bin/java" -XshowSettings:properties -version 2>&1 |
      sed -n 's/^ *java\.specification\.version = //p')"
  fi
  version="${version#1.}"
  echo "${version%%[.+-]*}"
}

find_java() {
  local best="" best_major=0 home major
  if [[ -n "${JAVA_HOME:-}" ]]; then
    major="$(jdk_major "$JAVA_HOME")"
    if [[ -n "$major" ]] && ((major >= 21)); then
      echo "$JAVA_HOME/bin/java"
      return
    fi
  fi
  for home in /usr/lib/jvm/*/; do
    home="${home%/}"
    [[ -L "$home" ]] && continue
    major="$(jdk_major "$home")"
    if [[ -n "$major" ]] && ((major > best_major)); then
      best="$home"
      best_major="$major"
    fi
  done
  if ((best_major < 21)); then
    echo "gals.sh: no JDK >= 21 (JAVA_HOME=${JAVA_HOME:-unset}, nothing newer under /usr/lib/jvm)" >&2
    exit 1
  fi
  echo "$best/bin/java"
}

java="$(find_java)"
if ((build)); then
  (cd "$root" && ./mvnw -B -q -pl benchmarks -am package -DskipTests) >&2
fi
[[ -f "$jar" ]] || { echo "gals.sh: $jar is missing; run without --no-build" >&2; exit 1; }

read -r -a opts <<<"${GALS_JAVA_OPTS:--Xms1g -Xmx1g}"
echo "# $("$java" -version 2>&1 | head -1); options: ${opts[*]}; $(nproc) cores" >&2
"$java" "${opts[@]}" "-Dgals.seconds=$seconds" -cp "$jar" org.armgals.bench.gals.Gals "${names[@]}"
