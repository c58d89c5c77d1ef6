# What the CLI test scripts share; each sources it after `promyk=$1 dir=$2`:
#   . "$(dirname "$0")/lib.sh"
# It empties and enters the work folder, makes promyk speak English whatever
# the machine's locale, and keeps the count that `summary` prints last in the
# form CTest's log readers know ("N passed, M failed") and returns as status.
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
export LANG=C.UTF-8 LC_ALL= LC_MESSAGES=
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { echo "FAIL: $*"; failed=$((failed + 1)); }
summary() {
  echo "$passed passed, $failed failed"
  [ "$failed" = 0 ]
}

# many_scene N M: a scene of N spheres and M lights with shadows, on standard
# output. Sphere 0 fills the pane's middle, the other spheres are small and
# behind the eye, every light is between the eye and sphere 0: so pixel
# (4, 4) of an 8 x 8 pane hits sphere 0, faces every light and tests every
# sphere on the way to each (N x M shadow tests; 1,500 x 1,500 make a trace
# of about 1 GB, past the trace limit).
many_scene() {
  awk -v n="$1" -v m="$2" 'BEGIN {
    printf "{\"name\": \"many\", \"shadows\": true, \"spheres\": [{\"S\": [0, 0, 6], \"r\": 3}"
    for (k = 1; k < n; k++) printf ", {\"S\": [%d, %d, -20], \"r\": 0.01}", k % 40, int(k / 40)
    printf "], \"lights\": ["
    for (k = 0; k < m; k++)
      printf "%s{\"L\": [%.3f, %.3f, 1], \"I\": 0.0001}", (k ? ", " : ""), (k % 40) / 40 - 0.5, int(k / 40) / 40 - 0.5
    printf "]}\n"
  }'
}
