#!/usr/bin/env bash
# Summarizes the output of savina.sh: benchmarks/savina-summary.sh [file...] (default: stdin)
#
# For each workload and implementation, the median ops_per_s of the measured runs (warm-up runs
# are ignored) and how many runs it is the median of; for mem, the median bytes per idle object.
# On the line of each other implementation (pekko, yardstick) whose workload armgals also ran, the
# column armgals/x is armgals' median / that implementation's: for ops_per_s above 1 means armgals
# is faster, for mem below 1 means armgals is smaller. cpu_s/M is the median of the runs' CPU
# seconds per million operations (the whole process's CPU during the timed part; equal to CPU
# microseconds per operation), and cpu armgals/x its ratio the same way: below 1 means armgals
# spends less CPU per operation. Output without CPU figures (older runs) leaves those columns blank.
set -euo pipefail
cat "$@" | awk '
  function field(name,   i, kv) {
    for (i = 1; i <= NF; i++) {
      split($i, kv, "=")
      if (kv[1] == name) return kv[2]
    }
    return ""
  }
  function median(key, what,   n, i, j, t, v) {
    n = count[what, key]
    for (i = 1; i <= n; i++) v[i] = values[what, key, i]
    for (i = 2; i <= n; i++) for (j = i; j > 1 && v[j - 1] > v[j]; j--) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
    return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
  }
  function add(name, impl, value, cpu,   key) {
    key = name SUBSEP impl
    if (!(("v", key) in count)) {
      order[++keys] = name
      if (!(impl in impls)) { impls[impl] = 1; implorder[++nimpl] = impl }
    }
    values["v", key, ++count["v", key]] = value
    if (cpu != "") values["c", key, ++count["c", key]] = cpu
  }
  $1 == "savina" { add(field("name"), field("impl"), field("ops_per_s"), field("cpu_s_per_m_ops")) }
  $1 == "mem" { add("mem", field("impl"), field("bytes_per_idle_object"), "") }
  END {
    printf "%-11s %-10s %14s %5s %10s %9s %14s\n", "workload", "impl", "median", "runs", "armgals/x", "cpu_s/M", "cpu armgals/x"
    for (k = 1; k <= keys; k++) {
      name = order[k]
      if (name in done) continue
      done[name] = 1
      a = name SUBSEP "armgals"
      for (i = 1; i <= nimpl; i++) {
        impl = implorder[i]
        key = name SUBSEP impl
        if (!(("v", key) in count)) continue
        m = median(key, "v")
        ratio = ""
        if (impl != "armgals" && (("v", a) in count) && m > 0)
          ratio = sprintf("%.2f", median(a, "v") / m)
        cpu = ""
        cpuratio = ""
        if (("c", key) in count) {
          c = median(key, "c")
          cpu = sprintf("%.3f", c)
          if (impl != "armgals" && (("c", a) in count) && c > 0)
            cpuratio = sprintf("%.2f", median(a, "c") / c)
        }
        printf "%-11s %-10s %14.0f %5d %10s %9s %14s\n", name, impl, m, count["v", key], ratio, cpu, cpuratio
      }
    }
  }'
