#!/bin/sh
# Outputs that are not regular files are never replaced (docs/bad_input.md, "Outputs that are not
# regular files"). Everything happens in the test's own folder DIR, never in /dev:
#   special_outputs.sh KIND VOXREF MAKE_BAD_INPUT GOOD.vxleb DIR
# KIND:
#   character_device  a null device made here (mknod c 1 3) as `decode --out` and as `render --out`:
#                     written through, still a character device afterwards
#   fifo              a FIFO as `decode --gradients-out`, read by cat: the reader gets exactly the
#                     bytes a regular file gets, and it is still a FIFO
#   socket            a Unix socket as `decode --out`: exit 2 naming it, still a socket, and the
#                     other output (--gradients-out) not written either
#   symlink           a link to a regular file as `decode --out`: the target gets the bytes, the
#                     link stays a link
# Every kind: no temporary file is left in DIR or in TMPDIR (set to DIR/tmp).
set -u
kind=$1 voxref=$2 mbi=$3 good=$4 dir=$5
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$dir" && mkdir -p "$dir/tmp" || fail "cannot make $dir"
export TMPDIR="$dir/tmp"

# The bytes a regular destination gets, to compare with.
"$voxref" decode --codec leb --input "$good" --out "$dir/data.raw" --gradients-out "$dir/grad.raw" > /dev/null || fail "regular decode"

case "$kind" in
  character_device)
    if ! mknod "$dir/null" c 1 3 2> /dev/null; then
      echo "VOXREF_TEST_SKIPPED: mknod needs root (CAP_MKNOD) to make a device node in the test's folder"
      exit 0
    fi
    "$voxref" decode --codec leb --input "$good" --out "$dir/null" || fail "decode into a character device exited $?"
    [ -c "$dir/null" ] || fail "the character device was replaced: $(ls -l "$dir/null")"
    mknod "$dir/null.exr" c 1 3 || fail "mknod"
    "$voxref" render --scene sparsegrid.hard.level1 --backend reference --out "$dir/null.exr" || fail "render into a character device exited $?"
    [ -c "$dir/null.exr" ] || fail "render replaced the character device: $(ls -l "$dir/null.exr")"
    ;;
  fifo)
    mkfifo "$dir/grad.fifo" || fail "mkfifo"
    cat "$dir/grad.fifo" > "$dir/grad.read" &
    reader=$!
    "$voxref" decode --codec leb --input "$good" --out "$dir/data2.raw" --gradients-out "$dir/grad.fifo" || fail "decode into a FIFO exited $?"
    wait "$reader" || fail "the reader of the FIFO failed"
    [ -p "$dir/grad.fifo" ] || fail "the FIFO was replaced: $(ls -l "$dir/grad.fifo")"
    cmp "$dir/grad.read" "$dir/grad.raw" || fail "the FIFO's reader got other bytes than a regular file"
    cmp "$dir/data2.raw" "$dir/data.raw" || fail "the data beside the FIFO differ"
    ;;
  socket)
    "$mbi" - "$dir/out.sock" socket || fail "cannot make a socket"
    out=$("$voxref" decode --codec leb --input "$good" --out "$dir/out.sock" --gradients-out "$dir/grad2.raw" 2>&1)
    status=$?
    [ "$status" -eq 2 ] || fail "decode into a socket exited $status, expected 2: $out"
    echo "$out" | grep -q "cannot write $dir/out.sock: it is a socket" || fail "the message does not name the socket: $out"
    [ -S "$dir/out.sock" ] || fail "the socket was replaced"
    [ ! -e "$dir/grad2.raw" ] || fail "the other output was written although the run failed"
    ;;
  symlink)
    printf 'an earlier output\n' > "$dir/target.raw"
    ln -s target.raw "$dir/link.raw" || fail "ln -s"
    "$voxref" decode --codec leb --input "$good" --out "$dir/link.raw" > /dev/null || fail "decode into a symbolic link exited $?"
    [ -L "$dir/link.raw" ] || fail "the symbolic link was replaced by a file"
    cmp "$dir/target.raw" "$dir/data.raw" || fail "the link's target does not hold the decoded bytes"
    ;;
  *) fail "unknown kind $kind" ;;
esac

left=$(find "$dir" -name '*.tmp*' -print)
[ -z "$left" ] || fail "temporary files left behind: $left"
[ -z "$(ls -A "$dir/tmp")" ] || fail "temporary files left in TMPDIR: $(ls -A "$dir/tmp")"
echo "ok: $kind"
