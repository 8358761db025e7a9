#!/usr/bin/env bash
# Checks what `./mvnw install` publishes, and that it is reproducible: it runs
# `./mvnw clean install -DskipTests` twice, each time into a local repository of its own in a
# temporary directory (the user's ~/.m2 is only read, as a tail: nothing is installed there;
# CHECK_ARTIFACTS_DIR names another place), and then
#  - for each library module: the jar, its -sources and -javadoc jars and its POM are installed,
#    the jar's manifest has the module's Automatic-Module-Name, and META-INF holds LICENSE and
#    NOTICE; armgals-bom and armgals-parent are installed, with url, scm, licenses and developers;
#  - NOTICE names every third-party artifact a published module brings at run time, with its
#    version (the first build lists them with dependency:list);
#  - every file installed under org/armgals (jars and POMs, not Maven's metadata files) has the
#    same SHA-256 in both builds.
# It takes two full builds without tests (minutes on two cores). Exit status 0 if all holds.
#
#   scripts/check-artifacts.sh            both builds and every check
#   scripts/check-artifacts.sh --once     one build, the checks of its contents only
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
version="$(sed -n 's:^  <version>\(.*\)</version>:\1:p' "$root/pom.xml" | head -1)"
work="${CHECK_ARTIFACTS_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/armgals-check-artifacts.XXXXXX")}"
library=(arm-active arm-representation arm-kernel arm-gals maam-framework maam-sim
  armgals-testkit armgals-testkit-maam examples)
declare -A module_name=(
  [arm-active]=org.armgals.active [arm-representation]=org.armgals.representation
  [arm-kernel]=org.armgals.kernel [arm-gals]=org.armgals.gals
  [maam-framework]=org.armgals.maam [maam-sim]=org.armgals.maam.sim
  [armgals-testkit]=org.armgals.testkit [armgals-testkit-maam]=org.armgals.testkit.maam
  [examples]=org.armgals.examples)
failures=0

fail() {
  echo "check-artifacts: FAILED: $*" >&2
  failures=$((failures + 1))
}

# Builds into $work/<name>/repository; the build's output goes to $work/<name>/build.log.
build() {
  local name="$1" repo="$work/$1/repository"
  rm -rf "${work:?}/$name"
  mkdir -p "$repo"
  echo "check-artifacts: build $name: ./mvnw clean install -DskipTests (local repository $repo)"
  local start=$SECONDS
  if ! (cd "$root" && ./mvnw -B clean install dependency:list -DskipTests \
    -Dmaven.repo.local="$repo" -Dmaven.repo.local.tail="$HOME/.m2/repository" \
    -DincludeScope=runtime -DexcludeGroupIds=org.armgals -DoutputFile=target/runtime-deps.txt) \
    >"$work/$name/build.log" 2>&1; then
    tail -40 "$work/$name/build.log" >&2
    echo "check-artifacts: FAILED: build $name failed (log: $work/$name/build.log)" >&2
    exit 1
  fi
  echo "check-artifacts: build $name took $((SECONDS - start)) s"
}

contents() {
  local repo="$work/$1/repository/org/armgals"
  local m dir jar
  for m in "${library[@]}"; do
    dir="$repo/$m/$version"
    for f in "$m-$version.jar" "$m-$version-sources.jar" "$m-$version-javadoc.jar" "$m-$version.pom"; do
      [[ -s "$dir/$f" ]] || fail "$m: $f not installed"
    done
    jar="$dir/$m-$version.jar"
    [[ -s "$jar" ]] || continue
    unzip -p "$jar" META-INF/MANIFEST.MF | tr -d '\r' |
      grep -qx "Automatic-Module-Name: ${module_name[$m]}" ||
      fail "$m: no Automatic-Module-Name: ${module_name[$m]} in its manifest"
    for f in META-INF/LICENSE META-INF/NOTICE; do
      unzip -l "$jar" "$f" >/dev/null 2>&1 || fail "$m: no $f in its jar"
    done
    unzip -l "$dir/$m-$version-javadoc.jar" index.html >/dev/null 2>&1 ||
      fail "$m: its javadoc jar has no index.html"
  done
  for pom in "$repo/armgals-bom/$version/armgals-bom-$version.pom" \
    "$repo/armgals-parent/$version/armgals-parent-$version.pom"; do
    [[ -s "$pom" ]] || { fail "$(basename "$pom") not installed"; continue; }
    for element in url scm licenses developers description; do
      grep -q "<$element[ >]" "$pom" || fail "$(basename "$pom") has no <$element>"
    done
  done
  echo "check-artifacts: build $1 installed $(find "$repo" -type f \( -name '*.jar' -o -name '*.pom' \) | wc -l) jars and POMs under org/armgals"
}

# Every runtime dependency of the published modules, artifactId and version, named in NOTICE.
notice() {
  local m artifact version listed=0
  for m in "${library[@]}"; do
    [[ -f "$root/$m/target/runtime-deps.txt" ]] || { fail "$m: no target/runtime-deps.txt"; continue; }
    while read -r artifact version; do
      listed=$((listed + 1))
      grep -qw -- "$artifact" "$root/NOTICE" || fail "NOTICE does not name $artifact ($m brings it)"
      grep -qF -- "$version" "$root/NOTICE" || fail "NOTICE does not name $artifact's version $version"
    done < <(awk -F: '/:jar:/ { print $2, $(NF - 1) }' "$root/$m/target/runtime-deps.txt" | sort -u)
  done
  echo "check-artifacts: NOTICE names all $listed runtime dependencies of the published modules (with repeats)"
}

checksums() {
  (cd "$work/$1/repository/org/armgals" &&
    find . -type f \( -name '*.jar' -o -name '*.pom' \) -print0 | sort -z | xargs -0 sha256sum)
}

build first
contents first
notice
if [[ "${1:-}" != "--once" ]]; then
  checksums first >"$work/first.sha256"
  build second
  contents second
  checksums second >"$work/second.sha256"
  if diff "$work/first.sha256" "$work/second.sha256" >"$work/differences.txt"; then
    echo "check-artifacts: reproducible: $(wc -l <"$work/first.sha256") files with the same SHA-256 in both builds"
  else
    fail "the two builds differ:"
    cat "$work/differences.txt" >&2
  fi
fi
if ((failures > 0)); then
  echo "check-artifacts: $failures check(s) failed" >&2
  exit 1
fi
echo "check-artifacts: passed (builds, logs and checksums in $work)"
