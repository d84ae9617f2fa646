# Checks on a run's stats.csv shared by the scene tests (sourced).
# stats_ok FILE: every value finite and every cloth edge strain below 100 %
# (a wall or a bad pin tears a sheet).
stats_ok() {
  if grep -qi "nan\|inf" "$1"; then echo "non-finite value in $1"; return 1; fi
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "max_stretch") c = i; next }
           c && $c + 0 > 1.0 { print "max_stretch " $c " at t = " $2; bad = 1 } END { exit bad }' "$1"
}
