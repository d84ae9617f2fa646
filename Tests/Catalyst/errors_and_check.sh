#!/bin/sh
# Catalyst's errors: a script that does not compile, a script that fails
# during the run, and a missing adaptor library each end the run with
# exit 2 and a message naming the file (and line); the first and the last
# before anything is written.
# usage: SOAK=... errors_and_check.sh SOURCE_DIR OUTDIR
set -u
src=$1
out=$2
scene="$src/Scenes/fig7_small.xml"
rm -rf "$out"
mkdir -p "$out"
failed=0
fail() { echo "FAILED: $*"; failed=1; }
expect() {  # expect NAME EXIT_CODE PATTERN -- soak run arguments...
  name=$1 code=$2 pattern=$3
  shift 4
  "$SOAK" run "$scene" -o "$out/$name" --frames 4 --device cpu --quiet "$@" >"$out/$name.log" 2>&1
  rc=$?
  [ $rc -eq "$code" ] || fail "$name: exit $rc, expected $code ($(tail -1 "$out/$name.log"))"
  grep -q "$pattern" "$out/$name.log" || fail "$name: the message lacks '$pattern':
$(tail -5 "$out/$name.log")"
}
printf 'from paraview.simple import *\ndef f(:\n    pass\n' >"$out/syntax.py"
expect syntax 2 "syntax.py\", line 2" -- --catalyst "$out/syntax.py"
[ -e "$out/syntax" ] && fail "syntax: the run wrote its folder"
printf 'from paraview.simple import *\nwater = TrivialProducer(registrationName="water")\ndef catalyst_execute(info):\n    if info.timestep > 2:\n        undefined_name(info)\n' >"$out/runtime.py"
expect runtime 2 "runtime.py\", line 5, in catalyst_execute" -- --catalyst "$out/runtime.py"
grep -q "runtime.py: the Catalyst script failed at frame" "$out/runtime.log" || fail "runtime: no closing message"
SOAK_CATALYST_LIBRARY="$out/no-such-adaptor.so" expect noadaptor 2 "built without ParaView's Catalyst" -- --live localhost:22222
[ -e "$out/noadaptor" ] && fail "noadaptor: the run wrote its folder"
expect badlive 2 "port must be a number" -- --live localhost:notaport
[ $failed -eq 0 ] && echo "Catalyst errors: exit 2 with file and line, nothing written before the run starts"
exit $failed
