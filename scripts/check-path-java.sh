#!/usr/bin/env bash
# Checks that the build runs the formatter (and every tool) on the toolchain JDK, whatever PATH
# holds: JAVA_HOME names a JDK >= 21 (scripts/java.sh finds one) and the first `java` on PATH is
# one that must never run. The build's root validate phase then selects the toolchain, runs the
# enforcer and checks the format of one probe file in Java 21 syntax (a record pattern, a guarded
# case) that an older parser rejects. It takes a Maven start and one formatter run.
#
#   scripts/check-path-java.sh              PATH starts with a `java` that fails if it is run
#   PATH_JDK=/usr/lib/jvm/java-17-openjdk-amd64 scripts/check-path-java.sh
#                                           PATH starts with that JDK's bin instead
#
# Exit status 0 if the check passed; the build's status and its output otherwise.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck source=scripts/java.sh
source "$root/scripts/java.sh"
java_home="$(dirname "$(dirname "$(find_java check-path-java)")")"

work="$root/target/path-java"
rm -rf "$work"
mkdir -p "$work/bin" "$work/probe"
if [[ -n "${PATH_JDK:-}" ]]; then
  [[ -x "$PATH_JDK/bin/java" ]] || { echo "check-path-java: no $PATH_JDK/bin/java" >&2; exit 2; }
  first="$PATH_JDK/bin"
  what="$("$first/java" -version 2>&1 | head -1)"
else
  first="$work/bin"
  what="a java that fails if run"
  for tool in java javac javadoc; do
    cat >"$first/$tool" <<EOF
#!/bin/sh
echo "check-path-java: PATH's $tool was run (\$*); the build must use the toolchain JDK" >&2
exit 97
EOF
    chmod +x "$first/$tool"
  done
fi

# Formatted as google-java-format formats it: the check passes on a parser of Java 21 or later.
cat >"$work/probe/Probe.java" <<'EOF'
package probe;

sealed interface Probe {
  record Point(int x, int y) implements Probe {}

  record Named(String name) implements Probe {}

  static String describe(Probe probe) {
    return switch (probe) {
      case Point(int x, int y) when x == y -> "diagonal " + x;
      case Point(int x, int y) -> x + "," + y;
      case Named n -> n.name();
    };
  }
}
EOF

echo "check-path-java: JAVA_HOME=$java_home, first on PATH: $first ($what)"
log="$work/build.log"
if ! (cd "$root" && JAVA_HOME="$java_home" PATH="$first:$PATH" ./mvnw -B -N validate \
  -Darmgals.format.includes=target/path-java/probe/Probe.java) >"$log" 2>&1; then
  cat "$log" >&2
  echo "check-path-java: FAILED: the build ran a tool that is not the toolchain JDK's" >&2
  exit 1
fi
grep -F 'Toolchain in exec-maven-plugin' "$log" || true
echo "check-path-java: passed: the formatter ran on the toolchain JDK"
