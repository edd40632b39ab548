#!/usr/bin/env bash
# full_disk.sh SPANLIGHT SOURCE_DIR
#
# `spanlight render` onto a real full disk: a 64 KiB tmpfs, filled first
# completely, then to 8 KiB short of full (the 21 KB PNG fails part way).
# Both times: exit 2, a message naming the output and the disk being full,
# the earlier output byte for byte as it was, and no temporary left. With
# room again the render succeeds. Exits 77 (ctest: skipped) when mounting is
# not permitted (not root, or no CAP_SYS_ADMIN in a container); the same
# failures are injected without a real disk in io_tests (atomic_write_test.cpp).
export SPANLIGHT=$1
source_dir=$2
# shellcheck source=tests/cli/cli_lib.sh
source "$source_dir/tests/cli/cli_lib.sh"

scene="$source_dir/scenes/horizon.json"  # 320 x 240: a 21 KB PNG
disk="$scratch/disk"
mkdir "$disk"
if ! mount -t tmpfs -o size=64k spanlight-full-disk "$disk" 2>/dev/null; then
  echo "SKIP: mounting a 64 KiB tmpfs is not permitted here"
  exit 77
fi
trap 'umount "$disk"; rm -rf "$scratch"' EXIT

make_previous_output "$disk/out.png"

# 1. Full from the start.
dd if=/dev/zero of="$disk/filler" bs=4096 2>/dev/null  # stops at "No space left on device"
run_spanlight render "$scene" --out "$disk/out.png"
expect_status 2
expect_stderr_has "$disk/out.png: --out: expected to "
expect_stderr_has "No space left on device"
expect_unchanged_previous_output "$disk/out.png"
expect_only_files "$disk" filler out.png

# 2. 8 KiB free: the write fails after its first 8 KiB.
rm "$disk/filler"
dd if=/dev/zero of="$disk/filler" bs=1024 count=52 2>/dev/null  # + 4 KiB for out.png: 8 KiB of 64 left
run_spanlight render "$scene" --out "$disk/out.png"
expect_status 2
expect_stderr_has "No space left on device"
expect_unchanged_previous_output "$disk/out.png"
expect_only_files "$disk" filler out.png

# 3. Room again: replaced by the picture.
rm "$disk/filler"
run_spanlight render "$scene" --out "$disk/out.png"
expect_status 0
[[ "$(png_size "$disk/out.png")" == "320 240" ]] || fail "out.png is not the 320 x 240 render"
expect_only_files "$disk" out.png

finish
