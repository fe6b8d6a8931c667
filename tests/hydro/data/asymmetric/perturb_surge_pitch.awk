# Makes the surge–pitch added mass of a WAMIT .1 file asymmetric: A15 × 0.9 and A51 × 1.1 in every
# row (finite periods and the PER = −1, 0 limits); every other value is copied verbatim.
# Run: awk -f perturb_surge_pitch.awk ../barge.1 > barge.1
NR == 1 { print; next }
($2 == 1 && $3 == 5) || ($2 == 5 && $3 == 1) {
  factor = ($2 == 1) ? 0.9 : 1.1
  if (NF == 4) printf "%14.6E%6d%6d%14.6E\n", $1, $2, $3, $4 * factor
  else printf "%14.6E%6d%6d%14.6E%14.6E\n", $1, $2, $3, $4 * factor, $5
  next
}
{ print }
