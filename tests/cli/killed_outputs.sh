#!/bin/sh
# A process ended by a signal leaves no temporary files (conformance/io/temporary_files.h). Each
# run is held in its last step, copying a finished temporary into a FIFO nobody reads yet, so the
# temporaries exist when the signal comes:
#   killed_outputs.sh KIND VOXREF GOOD.vxleb GOOD.raw.gz DIR      (GOOD.raw.gz: 32x32x16 uint8)
# KIND:
#   decode_sigterm  `decode --out FIFO --gradients-out G`: the data's temporary in TMPDIR, the
#                   gradients' beside G; SIGTERM removes both, and the exit status is SIGTERM's
#   encode_sigint   `encode --codec leb --out FIFO.vxleb`: the stream's temporary and the gradients'
#                   scratch file in TMPDIR; SIGINT removes both, the exit status is SIGINT's
#   decode_sigkill  the control: SIGKILL cannot be handled, so the same temporaries must still be
#                   there, which shows the other kinds look for files that exist
set -u
kind=$1 voxref=$2 good=$3 raw=$4 dir=$5
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$dir" && mkdir -p "$dir/tmp" || fail "cannot make $dir"
export TMPDIR="$dir/tmp"
mkfifo "$dir/out.fifo" "$dir/out.vxleb" || fail "mkfifo"

case "$kind" in
  decode_sigterm | decode_sigkill)
    "$voxref" decode --codec leb --input "$good" --out "$dir/out.fifo" --gradients-out "$dir/grad.raw" &
    expected=2 ;;
  encode_sigint)
    # A shell starts a background job with SIGINT ignored (POSIX, "Asynchronous Lists"), and voxref
    # keeps an ignored signal ignored; env gives it SIGINT's default back, as a terminal would.
    env --default-signal=INT "$voxref" encode --codec leb --input "$raw" --dims 32 32 16 --page-bits 8 --out "$dir/out.vxleb" &
    expected=2 ;;
  *) fail "unknown kind $kind" ;;
esac
pid=$!
temporaries() { find "$dir" -name '*.tmp*' -type f | wc -l; }
tries=0
while [ "$(temporaries)" -lt "$expected" ]; do
  tries=$((tries + 1))
  [ "$tries" -le 600 ] || { kill -KILL "$pid"; fail "the run never made its $expected temporary files"; }
  kill -0 "$pid" 2> /dev/null || fail "the run ended before it was signalled"
  sleep 0.1
done
sleep 0.3  # the temporaries are complete; the run waits for a reader of the FIFO

case "$kind" in
  decode_sigterm) signal=TERM number=15 ;;
  encode_sigint) signal=INT number=2 ;;
  decode_sigkill) signal=KILL number=9 ;;
esac
kill -"$signal" "$pid"
wait "$pid"
status=$?
[ "$status" -eq $((128 + number)) ] || fail "the run exited $status after SIG$signal, expected $((128 + number))"

left=$(find "$dir" -name '*.tmp*' -type f | wc -l)
if [ "$kind" = decode_sigkill ]; then
  [ "$left" -eq "$expected" ] || fail "after SIGKILL $left temporaries are left, expected $expected (the control)"
else
  [ "$left" -eq 0 ] || fail "temporary files left behind after SIG$signal: $(find "$dir" -name '*.tmp*')"
fi
[ ! -e "$dir/grad.raw" ] || fail "an output was renamed into place although the run was killed"
echo "ok: $kind"
