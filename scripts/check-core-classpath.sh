#!/usr/bin/env bash
# Checks what a user of arm-active gets from Maven (docs/decisions/0058), as a user would: it
# installs arm-active and its parents into a local repository of its own in a temporary directory
# (the user's ~/.m2 is only read, as a tail; CHECK_CORE_DIR names another place), then resolves
# three consumer projects and runs a program on each one's runtime class path:
#  - in-JVM: arm-active alone. At most 5 jars besides armgals' (SLF4J API included), none of
#    Jakarta Messaging, the Artemis client or server, or netty; scripts/consumer/InJvmUser.java runs
#    an active object and a filter and finds no jakarta.jms class;
#  - client: arm-active + artemis-jakarta-client. It holds every artifact artemis-jakarta-client
#    brings on its own (arm-active's exclusions take nothing from it; versions may be mediated);
#  - embedded: arm-active + artemis-jakarta-client + artemis-server, as docs/user-guide.md says;
#    scripts/consumer/DistributedUser.java starts an embedded broker, looks a name up over the
#    network and carries events.
# Exit status 0 if all holds. Run by .ci/run after the build.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
version="$(sed -n 's:^  <version>\(.*\)</version>:\1:p' "$root/pom.xml" | head -1)"
artemis="$(sed -n 's:.*<artemis.version>\(.*\)</artemis.version>.*:\1:p' "$root/pom.xml" | head -1)"
work="${CHECK_CORE_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/armgals-check-core.XXXXXX")}"
repo="$work/repository"
max_jars=5
# shellcheck source=java.sh
source "$root/scripts/java.sh"
java="$(find_java check-core-classpath)"
failures=0
mvn=("$root/mvnw" -B -q -Dmaven.repo.local="$repo" -Dmaven.repo.local.tail="$HOME/.m2/repository")

fail() {
  echo "check-core-classpath: FAILED: $*" >&2
  failures=$((failures + 1))
}

mkdir -p "$repo"
echo "check-core-classpath: installing arm-active into $repo"
if ! (cd "$root" && "${mvn[@]}" -pl arm-active -am install -DskipTests -Dmaven.javadoc.skip \
  -Dmaven.source.skip) >"$work/install.log" 2>&1; then
  tail -40 "$work/install.log" >&2
  echo "check-core-classpath: FAILED: installing arm-active (log: $work/install.log)" >&2
  exit 1
fi

# consumer <name> <extra dependencies...>: writes $work/<name>/pom.xml, lists its runtime
# dependencies in $work/<name>/deps.txt (groupId:artifactId:type[:classifier]:version) and its
# class path in $work/<name>/classpath.txt.
consumer() {
  local name="$1" dir="$work/$1" deps="" a
  shift
  mkdir -p "$dir"
  for a in "$@"; do
    deps+="<dependency><groupId>${a%%:*}</groupId><artifactId>$(cut -d: -f2 <<<"$a")</artifactId>"
    deps+="<version>$(cut -d: -f3 <<<"$a")</version></dependency>"
  done
  cat >"$dir/pom.xml" <<POM
<project xmlns="http://maven.apache.org/POM/4.0.0">
  <modelVersion>4.0.0</modelVersion>
  <groupId>org.example</groupId>
  <artifactId>armgals-user-$name</artifactId>
  <version>1</version>
  <dependencies>$deps</dependencies>
</project>
POM
  if ! "${mvn[@]}" -f "$dir/pom.xml" dependency:list dependency:build-classpath \
    -DincludeScope=runtime -DoutputFile="$dir/deps.raw" -Dmdep.outputFile="$dir/classpath.txt" \
    >"$dir/resolve.log" 2>&1; then
    tail -20 "$dir/resolve.log" >&2
    fail "$name: its dependencies do not resolve (log: $dir/resolve.log)"
    return 1
  fi
  sed -n 's/^ *\([^ :]*:[^ :]*:[^ ]*\):\(compile\|runtime\).*/\1/p' "$dir/deps.raw" | sort -u \
    >"$dir/deps.txt"
}

run() {
  local name="$1" program="$2"
  if "$java" --enable-native-access=ALL-UNNAMED -cp "$(cat "$work/$name/classpath.txt")" "$root/scripts/consumer/$program.java" \
    >"$work/$name/run.log" 2>&1; then
    echo "check-core-classpath: $name: $(tail -1 "$work/$name/run.log")"
  else
    tail -20 "$work/$name/run.log" >&2
    fail "$name: $program failed (log: $work/$name/run.log)"
  fi
}

active="org.armgals:arm-active:$version"
client="org.apache.artemis:artemis-jakarta-client:$artemis"
server="org.apache.artemis:artemis-server:$artemis"

if consumer in-jvm "$active"; then
  others="$(grep -v '^org\.armgals:' "$work/in-jvm/deps.txt" || true)"
  count="$(grep -c . <<<"$others" || true)"
  echo "check-core-classpath: in-jvm: $count jars besides armgals' (at most $max_jars):" $others
  ((count <= max_jars)) || fail "in-jvm: $count jars besides armgals', more than $max_jars"
  if grep -E '^(jakarta\.jms|io\.netty):|:artemis-(jakarta-client|core-client|server):' \
    <<<"$others"; then
    fail "in-jvm: a JMS, broker or netty jar reaches a user in one JVM"
  fi
  run in-jvm InJvmUser
fi

if consumer client-alone "$client" && consumer client "$active" "$client"; then
  missing="$(comm -23 <(cut -d: -f1,2 "$work/client-alone/deps.txt" | sort -u) \
    <(cut -d: -f1,2 "$work/client/deps.txt" | sort -u))"
  [[ -z "$missing" ]] || fail "client: arm-active takes from artemis-jakarta-client:" $missing
  echo "check-core-classpath: client: all $(wc -l <"$work/client-alone/deps.txt") jars of artemis-jakarta-client are there"
fi

if consumer embedded "$active" "$client" "$server"; then
  run embedded DistributedUser
fi

if ((failures > 0)); then
  echo "check-core-classpath: $failures check(s) failed" >&2
  exit 1
fi
echo "check-core-classpath: passed (logs in $work)"
