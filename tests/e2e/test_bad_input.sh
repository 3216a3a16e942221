#!/usr/bin/env bash
# Every bad input: exit 2, one clear line on stderr naming the problem, no output left.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
write_box_stl box.stl 10 10 10
"$NCVERIFY" -q sample box.stl -o good.samples --step 2

: >empty.stl
expect_bad_input "empty file" "empty.stl: empty file" out1 "$NCVERIFY" sample empty.stl -o out1
head -c 84 /dev/zero >zero.stl
expect_bad_input "zero triangles" "no triangles" out2 "$NCVERIFY" sample zero.stl -o out2
head -c 400 box.stl >cut.stl
expect_bad_input "binary STL cut mid-triangle" "claims 12 triangles" out3 "$NCVERIFY" sample cut.stl -o out3
/usr/bin/python3 -c "
import struct; open('huge.stl','wb').write(b'x'*80 + struct.pack('<I', 2000000000) + b'\1'*940)"
expect_bad_input "header claims 2e9 triangles" "claims 2000000000 triangles" out4 \
  "$NCVERIFY" sample huge.stl -o out4
/usr/bin/time -f "%M" -o mem.txt "$NCVERIFY" sample huge.stl -o out4 2>/dev/null
check "no huge allocation for an absurd count (peak < 64 MB)" test "$(cat mem.txt | tail -1)" -lt 65536
printf 'solid part\ngarbage garbage\n' >garbage.stl
expect_bad_input "ASCII STL with garbage" "ASCII STL, line 2" out5 "$NCVERIFY" sample garbage.stl -o out5
head -c 3000 /dev/urandom >random.stl
expect_bad_input "random bytes" "random.stl:" out6 "$NCVERIFY" sample random.stl -o out6
printf '\x89PNG\r\n\x1a\n' >image.stl; head -c 500 /dev/urandom >>image.stl
expect_bad_input "PNG renamed .stl" "PNG image" out7 "$NCVERIFY" sample image.stl -o out7
/usr/bin/python3 - <<'PY'
import struct
with open('nan.stl', 'wb') as f:
    f.write(b'\0' * 80 + struct.pack('<I', 1))
    f.write(struct.pack('<12f', 0, 0, 0, 0, 0, 0, 1, float('nan'), 0, 0, 1, 0) + b'\0\0')
PY
expect_bad_input "NaN coordinates" "NaN" out8 "$NCVERIFY" sample nan.stl -o out8
expect_bad_input "missing file" "nothere.stl: No such file" out9 "$NCVERIFY" sample nothere.stl -o out9
expect_bad_input "step zero" "invalid step '0'" out10 "$NCVERIFY" sample box.stl -o out10 --step 0
expect_bad_input "negative step" "invalid step '-1'" out11 "$NCVERIFY" sample box.stl -o out11 --step=-1
expect_bad_input "NaN step" "invalid step 'nan'" out12 "$NCVERIFY" sample box.stl -o out12 --step nan
expect_bad_input "absurd sample count" "use a larger step, or --force" out13 \
  "$NCVERIFY" sample box.stl -o out13 --step 1e-6
expect_bad_input "output folder missing" "nowhere/out.samples" "" \
  "$NCVERIFY" sample box.stl -o nowhere/out.samples
expect_bad_input "output to /dev/full" "/dev/full" "" "$NCVERIFY" sample box.stl -o /dev/full --step 2
if [ "$(id -u)" -ne 0 ]; then
  mkdir ro && chmod 555 ro
  expect_bad_input "read-only folder" "ro/out.samples" "" "$NCVERIFY" sample box.stl -o ro/out.samples
fi

# Intermediate files.
size=$(stat -c %s good.samples)
head -c $((size / 2)) good.samples >truncated.samples
expect_bad_input "truncated samples file" "truncated" "" "$NCVERIFY" inspect truncated.samples
cp good.samples flipped.samples
printf '\x55' | dd of=flipped.samples bs=1 seek=$((size - 100)) conv=notrunc status=none
expect_bad_input "flipped byte" "content hash mismatch" "" "$NCVERIFY" inspect flipped.samples
expect_bad_input "a mesh is not an intermediate file" "not an ncverify file" "" "$NCVERIFY" inspect box.stl
cp good.samples newer.samples
printf '\x09' | dd of=newer.samples bs=1 seek=12 conv=notrunc status=none
expect_bad_input "newer format version" "newer than this ncverify reads" "" "$NCVERIFY" inspect newer.samples
expect_bad_input "intermediate given as a mesh" "ncverify intermediate file" out14 \
  "$NCVERIFY" sample good.samples -o out14

# Standard input closed early.
expect_bad_input "stdin closed at once" "standard input: empty file" out15 \
  "$NCVERIFY" sample - -o out15 </dev/null
head -c 500 box.stl | expect_bad_input "stdin cut short" "claims 12 triangles" out16 \
  "$NCVERIFY" sample - -o out16
finish
