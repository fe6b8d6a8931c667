# keep the header, rigid modes 1,3,5 (both indices for .1/.hst, mode index for .3), PER -1 and 0,
# finite periods 0.9-30 s (every step) and every 10th step (1.5 s) beyond 30 s.
function keep_period(p,  n) { if (p <= 0) return 1; n = int(p / 0.15 + 0.5); return (n >= 6 && n <= 200) || (n > 200 && n % 10 == 0) }
function rigid(m) { return m == 1 || m == 3 || m == 5 }
NR == 1 { print; next }
kind == "1" { if (keep_period($1) && rigid($2) && rigid($3)) print; next }
kind == "3" { if (keep_period($1) && rigid($3)) print; next }
kind == "hst" { if (rigid($1) && rigid($2)) print; next }
