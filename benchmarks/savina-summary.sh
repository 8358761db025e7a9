#!/usr/bin/env bash
# Summarizes the output of savina.sh: benchmarks/savina-summary.sh [file...] (default: stdin)
#
# For each workload and implementation, the median ops_per_s of the measured runs (warm-up runs
# are ignored) and how many runs it is the median of; for mem, the median bytes per idle object.
# On the line of each other implementation (pekko, yardstick) whose workload armgals also ran, the
# last column is armgals / that implementation: for ops_per_s above 1 means armgals is faster, for
# mem below 1 means armgals is smaller.
set -euo pipefail
cat "$@" | awk '
  function field(name,   i, kv) {
    for (i = 1; i <= NF; i++) {
      split($i, kv, "=")
      if (kv[1] == name) return kv[2]
    }
    return ""
  }
  function median(key,   n, i, j, t, v) {
    n = count[key]
    for (i = 1; i <= n; i++) v[i] = values[key, i]
    for (i = 2; i <= n; i++) for (j = i; j > 1 && v[j - 1] > v[j]; j--) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
    return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
  }
  function add(name, impl, value,   key) {
    key = name SUBSEP impl
    if (!(key in count)) {
      order[++keys] = name
      if (!(impl in impls)) { impls[impl] = 1; implorder[++nimpl] = impl }
    }
    values[key, ++count[key]] = value
  }
  $1 == "savina" { add(field("name"), field("impl"), field("ops_per_s")) }
  $1 == "mem" { add("mem", field("impl"), field("bytes_per_idle_object")) }
  END {
    printf "%-11s %-10s %14s %5s %10s\n", "workload", "impl", "median", "runs", "armgals/x"
    for (k = 1; k <= keys; k++) {
      name = order[k]
      if (name in done) continue
      done[name] = 1
      for (i = 1; i <= nimpl; i++) {
        impl = implorder[i]
        key = name SUBSEP impl
        if (!(key in count)) continue
        m[impl] = median(key)
        ratio = ""
        if (impl != "armgals" && ((name SUBSEP "armgals") in count) && m[impl] > 0)
          ratio = sprintf("%.2f", median(name SUBSEP "armgals") / m[impl])
        printf "%-11s %-10s %14.0f %5d %10s\n", name, impl, m[impl], count[key], ratio
      }
    }
  }'
