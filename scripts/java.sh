# Finds a JDK >= 21 for the scripts of this repository; source it, then call find_java <who> (and
# armgals_jvm_options for the options ./armgals runs its JVM with).
# JAVA_HOME wins if it is one; otherwise the newest JDK under /usr/lib/jvm, ~/.sdkman and ~/.jdks.

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

# Prints the path of the java launcher to use; exits with a message naming $1 if there is none.
find_java() {
  local who="$1" best="" best_major=0 home major
  if [[ -n "${JAVA_HOME:-}" ]]; then
    major="$(jdk_major "$JAVA_HOME")"
    if [[ -n "$major" ]] && ((major >= 21)); then
      echo "$JAVA_HOME/bin/java"
      return
    fi
  fi
  for home in /usr/lib/jvm/*/ "$HOME"/.sdkman/candidates/java/*/ "$HOME"/.jdks/*/; do
    home="${home%/}"
    [[ -d "$home" && ! -L "$home" ]] || continue
    major="$(jdk_major "$home")"
    if [[ -n "$major" ]] && ((major > best_major)); then
      best="$home"
      best_major="$major"
    fi
  done
  if ((best_major < 21)); then
    echo "$who: no JDK >= 21 found (JAVA_HOME=${JAVA_HOME:-unset}; looked under /usr/lib/jvm, ~/.sdkman, ~/.jdks); install one or set JAVA_HOME" >&2
    exit 1
  fi
  echo "$best/bin/java"
}

# Prints, on one line, the JVM options ./armgals gives the java launcher at $1, the user's own
# options being $2: native access for Artemis' libaio and netty's use of sun.misc.Unsafe allowed
# from JDK 23 (so that JDK 24 and later do not warn; the jar's manifest enables native access), and
# ZGC, generational, unless $2 names a collector (two collectors stop the JVM). A paced run's cycle
# is 10 ms, and G1's young pauses on a 2-core machine took 10 to 70 ms each, every one a missed
# cycle; ZGC's stay under a millisecond, at no cost to a run in virtual time (decision 0069).
armgals_jvm_options() {
  local major
  major="$(jdk_major "$(dirname "$(dirname "$1")")")"
  local options=(--enable-native-access=ALL-UNNAMED)
  if ((major >= 23)); then
    options+=(--sun-misc-unsafe-memory-access=allow)
  fi
  if [[ ! "$2" =~ -XX:[+]Use[A-Za-z0-9]*GC ]]; then
    options+=(-XX:+UseZGC)
    ((major >= 23)) || options+=(-XX:+ZGenerational)
  fi
  echo "${options[*]}"
}
