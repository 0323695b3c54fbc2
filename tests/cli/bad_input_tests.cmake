# The bad-input catalogue (issue 8), end to end through the command line: docs/bad_input.md lists
# every entry. For each input the command line reads, bad variants are made at test time from good
# files that voxref itself wrote (make_bad_input edits them by the format documents' offsets), and
# each must be refused with exit status 2, a message that names the file, the offset or field and
# what was expected, and nothing left behind (check_bad_input.cmake). Resource limits: the entries
# with ULIMIT_V run under `ulimit -v` (1 GB), where an allocation of what a header claims would end
# in std::bad_alloc instead of the clear message. Included from tests/CMakeLists.txt (voxref_expect,
# voxref_bin, test_out). Label: badinput.
set(bi "${test_out}/badinput")
set(good "${bi}/good")

add_executable(make_bad_input cli/make_bad_input.cpp)
target_link_libraries(make_bad_input PRIVATE nlohmann_json::nlohmann_json ZLIB::ZLIB)
voxref_warnings(make_bad_input)
set(mbi "$<TARGET_FILE:make_bad_input>")

function(bi_regex_escape in out)
  string(REGEX REPLACE "([][+.*()^$?|\\{}])" "\\\\\\1" r "${in}")
  set(${out} "${r}" PARENT_SCOPE)
endfunction()

# voxref_bad_input(NAME COMMAND a|b EXPECT regex [EXIT 2] [MAKE cmd|args] [MAKE2 ...] [PRE f|g]
#                  [MKDIRS d|e] [UNWRITABLE d] [ULIMIT_V kib] [ENVIRONMENT A=1] [NEEDS fixtures])
# <DIR> is the entry's own folder (${bi}/t/NAME), <GOOD> the folder of the good files; in EXPECT,
# <DIR> is matched literally.
function(voxref_bad_input name)
  cmake_parse_arguments(ARG "" "COMMAND;EXPECT;EXIT;MAKE;MAKE2;PRE;MKDIRS;UNWRITABLE;ULIMIT_V;ENVIRONMENT;NEEDS" "" ${ARGN})
  set(dir "${bi}/t/${name}")
  bi_regex_escape("${dir}" dirRegex)
  foreach(v COMMAND MAKE MAKE2 ENVIRONMENT)
    string(REPLACE "<DIR>" "${dir}" ARG_${v} "${ARG_${v}}")
    string(REPLACE "<GOOD>" "${good}" ARG_${v} "${ARG_${v}}")
  endforeach()
  string(REPLACE "<DIR>" "${dirRegex}" ARG_EXPECT "${ARG_EXPECT}")
  if(NOT ARG_EXIT)
    set(ARG_EXIT 2)
  endif()
  add_test(NAME badinput.${name}
           COMMAND ${CMAKE_COMMAND} "-DDIR=${dir}" "-DCOMMAND=${ARG_COMMAND}" "-DEXPECT=${ARG_EXPECT}" "-DEXPECT_EXIT=${ARG_EXIT}"
                   "-DMAKE=${ARG_MAKE}" "-DMAKE2=${ARG_MAKE2}" "-DPRE=${ARG_PRE}" "-DMKDIRS=${ARG_MKDIRS}" "-DUNWRITABLE=${ARG_UNWRITABLE}"
                   "-DULIMIT_V=${ARG_ULIMIT_V}" "-DENVIRONMENT=${ARG_ENVIRONMENT}" -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/check_bad_input.cmake")
  # Under the sanitizers an address-space limit cannot work (ASan reserves terabytes of shadow).
  set(labels "badinput;cli;sanitize")
  if(ARG_ULIMIT_V)
    set(labels "badinput;cli;resource_limit")
  endif()
  set_tests_properties(badinput.${name} PROPERTIES LABELS "${labels}" TIMEOUT 300 SKIP_REGULAR_EXPRESSION "VOXREF_TEST_SKIPPED:"
                       FIXTURES_REQUIRED "${ARG_NEEDS}")
endfunction()

# --- The good files, each written by voxref (or derived from one with zlib's gzip) ---------------
add_test(NAME badinput.good.clean COMMAND sh -c "rm -rf \"$0\" && mkdir -p \"$0\"" "${good}")
set_tests_properties(badinput.good.clean PROPERTIES FIXTURES_SETUP bi_clean LABELS "badinput;cli;sanitize")
voxref_expect(badinput.good.plume COMMAND "${voxref_bin}|encode|--codec|timevarying|--plume|--side|16|--steps|2|--out|${good}/plume.vxtv"
              EXIT 0 SETS bi_plume NEEDS bi_clean LABELS "badinput;cli;sanitize")
# A raw volume: the first time step of the plume, 16384 bytes (32x32x16 uint8, or 32x16x16 uint16).
voxref_expect(badinput.good.volume COMMAND "${voxref_bin}|decode|--codec|timevarying|--input|${good}/plume.vxtv|--step|0|--out|${good}/steps"
              EXIT 0 SETS bi_volume NEEDS "bi_clean;bi_plume" LABELS "badinput;cli;sanitize")
voxref_expect(badinput.good.volume_gz COMMAND "${mbi}|${good}/steps/step_000.rgba|${good}/volume.raw.gz|gzip"
              EXIT 0 SETS bi_volume_gz NEEDS "bi_clean;bi_volume" LABELS "badinput;cli;sanitize")
voxref_expect(badinput.good.leb
  COMMAND "${voxref_bin}|encode|--codec|leb|--input|${good}/volume.raw.gz|--dims|32|32|16|--page-bits|8|--out|${good}/volume.vxleb|--bounds-out|${good}/volume.vxlbb"
  EXIT 0 OUTPUT "pages +71 stored of the grid's 141, each 256 points" SETS bi_leb NEEDS "bi_clean;bi_volume_gz" LABELS "badinput;cli;sanitize")
# A thin volume, 513x1x1: a small stream whose grid is 513^3 (k = 9); its padding costs nothing.
voxref_expect(badinput.good.thin_raw COMMAND "${mbi}|${good}/steps/step_000.rgba|${good}/thin.raw|truncate:513"
              EXIT 0 SETS bi_thin_raw NEEDS "bi_clean;bi_volume" LABELS "badinput;cli")
voxref_expect(badinput.good.thin COMMAND "${voxref_bin}|encode|--codec|leb|--input|${good}/thin.raw|--dims|513|1|1|--page-bits|20|--out|${good}/thin.vxleb"
              EXIT 0 OUTPUT "grid +513\\^3 \\(k = 9" SETS bi_thin NEEDS "bi_clean;bi_thin_raw" LABELS "badinput;cli")
# A gzip bomb: 2 GiB of zeros in 9 MB.
voxref_expect(badinput.good.bomb COMMAND "${mbi}|-|${good}/bomb.raw.gz|gzip-zeros:2147483648"
              EXIT 0 SETS bi_bomb NEEDS bi_clean LABELS "badinput;cli")
voxref_expect(badinput.good.report COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|${good}/report"
              EXIT 0 SETS bi_report NEEDS bi_clean LABELS "badinput;cli;sanitize")
voxref_expect(badinput.good.fixtures COMMAND "${voxref_bin}|fixtures|generate|--dir|${good}/fx|--scene|blobs_not_a_cube|--frames|1"
              EXIT 0 SETS bi_fixtures NEEDS bi_clean LABELS "badinput;cli;sanitize")
# Scenes of both systems that `voxref render` reads (conformance/modules/sparsegrid/SCENE.md; timevarying_scene.h), rendered once
# to show they are good.
file(WRITE "${bi}/scenes/sparsegrid.json"
  "{\"system\": \"sparsegrid\", \"data\": {\"volume\": \"${good}/steps/step_000.rgba\", \"dims\": [32, 32, 16]}, \"level\": 3, \"image\": [8, 8], \"planes\": 4}\n")
file(WRITE "${bi}/scenes/timevarying.json"
  "{\"system\": \"timevarying\", \"data\": \"blobs\", \"side\": 16, \"steps\": 2, \"level\": 1, \"composite\": true, \"frame\": \"orbit\", \"image\": [8, 8], \"planes\": 4}\n")
foreach(system sparsegrid timevarying)
  voxref_expect(badinput.good.scene_${system} COMMAND "${voxref_bin}|render|--scene|${bi}/scenes/${system}.json|--out|${good}/${system}.exr"
                EXIT 0 OUTPUT "wrote .*${system}.exr \\(8x8, reference\\)" SETS bi_scene_${system} NEEDS "bi_clean;bi_volume" LABELS "badinput;cli;sanitize")
endforeach()

set(tv_decode "${voxref_bin}|decode|--codec|timevarying|--input")
set(leb_decode "${voxref_bin}|decode|--codec|leb|--input")
set(thirteen_digits "[0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9]")

# --- .vxtv (reference/timevarying/FORMAT.md) through `voxref decode`: the output folder must not
# appear, or (PRE) keep its earlier step file unchanged. Header offsets: magic 0, version 4, flags
# 6, side 8, time_steps 12, level 16, cells 20, block_side 24, index_slots 28, block_slots 32,
# encoding 48, distinct_blocks 52, homogeneous 56, refined 64; the transfer function at 96 (name
# length, the name "plume", then 1024 bytes from 102); the index texture at 1126; the CRC-32 last.
set(tv_make "${mbi}|<GOOD>/plume.vxtv|<DIR>/bad.vxtv")
set(tv_run "${tv_decode}|<DIR>/bad.vxtv|--out|<DIR>/steps")
voxref_bad_input(vxtv.empty MAKE "${tv_make}|truncate:0" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 0: magic: expected 4 bytes")
voxref_bad_input(vxtv.truncated_in_header MAKE "${tv_make}|truncate:50" COMMAND "${tv_run}" NEEDS bi_plume PRE "steps/step_000.rgba"
  EXPECT "<DIR>/bad\\.vxtv: offset 50: reserved: expected 2 bytes")
voxref_bad_input(vxtv.truncated_in_transfer_function MAKE "${tv_make}|truncate:150" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 102: transfer function table: expected 1024 bytes")
voxref_bad_input(vxtv.truncated_in_textures MAKE "${tv_make}|truncate:-100" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 1126: [^\n]*describes [0-9]+ bytes[^\n]*has [0-9]+ \\(truncated\\)")
voxref_bad_input(vxtv.unsupported_version MAKE "${tv_make}|u16:4=2" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 4: version: expected 1, got 2")
voxref_bad_input(vxtv.flags MAKE "${tv_make}|u16:6=1" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 6: flags: expected 0, got 1")
voxref_bad_input(vxtv.side_not_a_power_of_two MAKE "${tv_make}|u32:8=12" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 8: side: expected a power of two, got 12")
voxref_bad_input(vxtv.side_out_of_range MAKE "${tv_make}|u32:8=1024" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 8: side: expected 4\\.\\.512, got 1024")
voxref_bad_input(vxtv.no_time_steps MAKE "${tv_make}|u32:12=0" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 12: time_steps: expected 1\\.\\.65536, got 0")
voxref_bad_input(vxtv.index_slots_too_few MAKE "${tv_make}|u32:28=1" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 28: index_slots: expected a power of two S with S\\^3 >= 2")
voxref_bad_input(vxtv.unknown_encoding MAKE "${tv_make}|u8:48=9" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 48: encoding: expected 0\\.\\.3, got 9")
voxref_bad_input(vxtv.distinct_blocks_beyond_the_slots MAKE "${tv_make}|u32:52=0xffffffff" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 52: distinct_blocks: 4294967295 exceeds the [0-9]+ block slots")
voxref_bad_input(vxtv.cell_counts_inconsistent MAKE "${tv_make}|u64:64=1" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 64: refined_cells: homogeneous \\+ refined must be 128")
voxref_bad_input(vxtv.transfer_function_name_empty MAKE "${tv_make}|u8:96=0" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 96: transfer function name length: expected 1\\.\\.64, got 0")
voxref_bad_input(vxtv.trailing_bytes MAKE "${tv_make}|append:xx" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 1126: [^\n]*describes [0-9]+ bytes[^\n]*has [0-9]+ \\(trailing bytes\\)")
voxref_bad_input(vxtv.checksum_mismatch MAKE "${tv_make}|flip:2000" COMMAND "${tv_run}" NEEDS bi_plume PRE "steps/step_000.rgba"
  EXPECT "<DIR>/bad\\.vxtv: offset [0-9]+: trailer: CRC-32 mismatch")
# No block stored, CRC-32 made right again: every refinement address of the index is now outside.
voxref_bad_input(vxtv.refinement_address_outside_the_blocks MAKE "${tv_make}|u32:52=0|crc32:0:-4:-4" COMMAND "${tv_run}" NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset [0-9]+: index texel [0-9]+: refinement address \\([0-9]+, [0-9]+, [0-9]+\\) is not one of the 0 blocks")
voxref_bad_input(vxtv.input_is_a_directory MKDIRS "adir.vxtv" COMMAND "${tv_decode}|<DIR>/adir.vxtv|--out|<DIR>/steps" NEEDS bi_plume
  EXPECT "<DIR>/adir\\.vxtv is not a regular file")
voxref_bad_input(vxtv.step_out_of_range MAKE "${mbi}|<GOOD>/plume.vxtv|<DIR>/good.vxtv" COMMAND "${tv_decode}|<DIR>/good.vxtv|--step|7|--out|<DIR>/steps"
  NEEDS bi_plume EXPECT "--step 7 is outside 0\\.\\.1")
voxref_bad_input(vxtv.step_negative MAKE "${mbi}|<GOOD>/plume.vxtv|<DIR>/good.vxtv" COMMAND "${tv_decode}|<DIR>/good.vxtv|--step|-5|--out|<DIR>/steps"
  NEEDS bi_plume EXPECT "--step -5 is outside 0\\.\\.1")
# 65,537 time steps (one more than the container holds) are refused before any input is read: the
# files need not exist (the shell repeats the name v; no ';' or '|', which the catalogue splits on).
voxref_bad_input(option.time_steps_beyond_the_container
  COMMAND "sh|-c|set -- $(printf 'v %.0s' $(seq 65537)) && exec \"$0\" encode --codec timevarying --dims 1 1 1 --out <DIR>/out.vxtv --input \"$@\"|${voxref_bin}"
  EXPECT "--input: 65537 time steps. the \\.vxtv container holds 1\\.\\.65536")
voxref_bad_input(vxtv.out_is_a_regular_file MAKE "${mbi}|<GOOD>/plume.vxtv|<DIR>/good.vxtv" COMMAND "${tv_decode}|<DIR>/good.vxtv|--out|<DIR>/steps"
  PRE "steps" NEEDS bi_plume EXPECT "cannot create directory <DIR>/steps")
# Resource limit: a header whose every field agrees (side 512, 65536 steps, level 7: 128^3 cells of
# 4^3, 64^3 index slots, 4096^3 block slots, all cells homogeneous) claims a 2.2 TB index texture
# and a 17.6 TB refinement texture; the file has 5 KB.
voxref_bad_input(vxtv.huge_claim
  MAKE "${tv_make}|u32:8=512|u32:12=65536|u32:16=7|u32:20=128|u32:24=4|u32:28=64|u32:32=4096|u64:56=137438953472|u64:64=0"
  COMMAND "${tv_run}" ULIMIT_V 1000000 NEEDS bi_plume
  EXPECT "<DIR>/bad\\.vxtv: offset 1126: the header describes ${thirteen_digits}[0-9]* bytes in all, the file has [0-9]+ \\(truncated\\)")

# --- .vxleb (reference/leb/FORMAT.md) through `voxref decode`/`info`: header CRC at 32 over bytes
# 0..31 (remade with crc32:0:32:32 to reach a field); the data channel's descriptor at 36: kind 36,
# page_count 40 (141 pages of 2^8 for the 33^3 grid), stored_pages 44 (71: the others hold padding
# alone), payload_bytes 48, code lengths 56 (9 x 9), stored page indices 137, page lengths 421,
# page CRCs 705, descriptor CRC 989 (over 36..988).
set(leb_make "${mbi}|<GOOD>/volume.vxleb|<DIR>/bad.vxleb")
set(leb_run "${leb_decode}|<DIR>/bad.vxleb|--out|<DIR>/volume.raw|--gradients-out|<DIR>/volume.grad")
set(hcrc "crc32:0:32:32")
voxref_bad_input(vxleb.empty MAKE "${leb_make}|truncate:0" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 0: magic: expected 4 bytes")
voxref_bad_input(vxleb.truncated_in_header MAKE "${leb_make}|truncate:20" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 4: header: expected 32 bytes")
voxref_bad_input(vxleb.truncated_in_descriptor MAKE "${leb_make}|truncate:100" COMMAND "${leb_run}" NEEDS bi_leb PRE "volume.raw"
  EXPECT "<DIR>/bad\\.vxleb: offset 24: total_bytes: [^\n]*describes [0-9]+ bytes, the stream has 100 \\(truncated\\)")
voxref_bad_input(vxleb.truncated_in_pages MAKE "${leb_make}|truncate:-1" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 24: total_bytes: [^\n]*describes [0-9]+ bytes, the stream has [0-9]+ \\(truncated\\)")
voxref_bad_input(vxleb.header_checksum_mismatch MAKE "${leb_make}|u16:4=3" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 32: header_crc: CRC-32 mismatch")
voxref_bad_input(vxleb.unsupported_version MAKE "${leb_make}|u16:4=5|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 4: version: expected 2 \\(lead-1\\), 3 \\(adaptive\\) or 4 \\(context\\), got 5")
voxref_bad_input(vxleb.version_1 MAKE "${leb_make}|u16:4=1|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 4: version: expected 2 \\(lead-1\\), 3 \\(adaptive\\) or 4 \\(context\\), got 1 \\(version 1 streams[^\n]*encode the volume again\\)")
# Header byte 22, the coder, is the version's (a lead-1 stream relabelled as version 3, and a
# version 2 stream claiming the adaptive coder), and byte 23 (the gradients) is 0 or 1, and 1 only
# without a gradients channel.
voxref_bad_input(vxleb.version_3_with_lead1_coder MAKE "${leb_make}|u16:4=3|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 22: coder: a version 3 stream has coder 1 \\(adaptive\\), got 0")
voxref_bad_input(vxleb.version_2_with_adaptive_coder MAKE "${leb_make}|u8:22=1|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 22: coder: a version 2 stream has coder 0 \\(lead-1\\), got 1")
voxref_bad_input(vxleb.gradients_byte MAKE "${leb_make}|u8:23=2|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 23: gradients: expected 0\\.\\.1, got 2")
voxref_bad_input(vxleb.derived_gradients_beside_a_channel MAKE "${leb_make}|u8:23=1|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 23: gradients: 1 \\(derived from the data\\) with 2 channels")
voxref_bad_input(vxleb.sample_bits MAKE "${leb_make}|u8:6=12|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 6: sample_bits: expected 8 or 16, got 12")
voxref_bad_input(vxleb.k_not_the_smallest_grid MAKE "${leb_make}|u8:7=9|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 7: k: 9 is not the smallest grid covering 32x32x16 \\(expected 5\\)")
voxref_bad_input(vxleb.extent_zero MAKE "${leb_make}|u32:8=0|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 8: extent: expected 1\\.\\.33, got 0")
voxref_bad_input(vxleb.page_bits_out_of_range MAKE "${leb_make}|u8:20=3|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 20: page_bits: expected 4\\.\\.20, got 3")
voxref_bad_input(vxleb.channel_count MAKE "${leb_make}|u8:21=3|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 21: channel_count: expected 1\\.\\.2, got 3")
voxref_bad_input(vxleb.trailing_bytes MAKE "${leb_make}|append:xx" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 24: total_bytes: [^\n]*\\(trailing bytes\\)")
voxref_bad_input(vxleb.channel_kind MAKE "${leb_make}|u8:36=1" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 36: kind: channel 0 must be 0 \\(data\\)")
voxref_bad_input(vxleb.page_count MAKE "${leb_make}|u32:40=1099" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 40: page_count: expected 141[^\n]*got 1099")
voxref_bad_input(vxleb.stored_pages_zero MAKE "${leb_make}|u32:44=0" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 44: stored_pages: expected 1\\.\\.141, got 0")
voxref_bad_input(vxleb.code_length_too_long MAKE "${leb_make}|u8:57=13" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 56: code lengths: [^\n]*13 bits, more than the 12 allowed")
voxref_bad_input(vxleb.descriptor_checksum_mismatch MAKE "${leb_make}|flip:800" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 989: descriptor crc: CRC-32 mismatch")
voxref_bad_input(vxleb.page_checksum_mismatch MAKE "${leb_make}|flip:-1" COMMAND "${leb_run}" NEEDS bi_leb PRE "volume.raw|volume.grad"
  EXPECT "<DIR>/bad\\.vxleb: offset [0-9]+: gradients page [0-9]+: CRC-32 mismatch")
# The header says 33x32x16 (same grid, header CRC remade): the pages hold too few deltas.
voxref_bad_input(vxleb.extent_inconsistent_with_the_pages MAKE "${leb_make}|u32:8=33|${hcrc}" COMMAND "${leb_run}" NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset [0-9]+: data page [0-9]+[: ]")
voxref_bad_input(vxleb.missing COMMAND "${leb_decode}|<DIR>/none.vxleb|--out|<DIR>/volume.raw" NEEDS bi_leb
  EXPECT "<DIR>/none\\.vxleb does not exist")
# Resource limits. payload_bytes of 2^40 (descriptor CRC remade):
voxref_bad_input(vxleb.payload_claims_a_terabyte MAKE "${leb_make}|u64:48=1099511627776|crc32:36:989:989" COMMAND "${leb_run}"
  ULIMIT_V 1000000 NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 48: payload_bytes: 1099511627776[^\n]*pages add up to [0-9]+")
# The largest grid (k = 10, 1025^3) in pages of 2^4, every page claimed stored: a page table of
# 807667984 bytes (67305665 pages x 12 + 4) claimed by a stream of 10 KB.
voxref_bad_input(vxleb.page_table_claims_half_a_gigabyte
  MAKE "${leb_make}|u8:7=10|u32:8=1025|u32:12=1025|u32:16=1025|u8:20=4|${hcrc}|u32:40=67305665|u32:44=67305665" COMMAND "${leb_run}"
  ULIMIT_V 1000000 NEEDS bi_leb
  EXPECT "<DIR>/bad\\.vxleb: offset 137: page table: expected 807667984 bytes, the stream ends after [0-9]+")
# Padding for free: the 513x1x1 stream in its 513^3 grid decodes within 1 GB of address space
# (before version 2 it needed the whole grid, 1.1 GB, and was refused), and gives its samples back.
voxref_expect(badinput.vxleb.thin_volume_decodes_in_what_its_samples_need
  COMMAND "sh|-c|ulimit -v 1000000 && \"$0\" decode --codec leb --input \"$1\" --out \"$2\" && cmp \"$2\" \"$3\"|${voxref_bin}|${good}/thin.vxleb|${good}/thin_decoded.raw|${good}/thin.raw"
  EXIT 0 OUTPUT "decoded 513x1x1 uint8 samples" NEEDS bi_thin LABELS "badinput;cli")
# Encoding a volume whose samples need more than the limit: refused from the extents, before the
# volume is read (it was a bare std::bad_alloc).
voxref_bad_input(vxleb.encode_volume_needs_more_than_the_limit MAKE "${mbi}|<GOOD>/steps/step_000.rgba|<DIR>/thin.raw|truncate:1025"
  COMMAND "${voxref_bin}|encode|--codec|leb|--input|<DIR>/thin.raw|--dims|1024|1024|1024|--out|<DIR>/thin.vxleb" ULIMIT_V 1000000 NEEDS bi_volume
  EXPECT "<DIR>/thin\\.raw: encoding needs [0-9]+ bytes \\(1024x1024x1024 samples in the 1025\\^3 grid of k = 10[^\n]*more than[^\n]*\\(ulimit -v\\)")

# --- Raw volumes and gzip (conformance/io/raw_volume.h): --input of `voxref encode`, --volume of
# `voxref fixtures generate`. The good volume holds 16384 bytes: 32x32x16 uint8.
set(raw_make "${mbi}|<GOOD>/steps/step_000.rgba|<DIR>/bad.raw")
set(gz_make "${mbi}|<GOOD>/volume.raw.gz|<DIR>/bad.raw.gz")
set(leb_encode "${voxref_bin}|encode|--codec|leb|--out|<DIR>/out.vxleb|--input")
set(tv_encode "${voxref_bin}|encode|--codec|timevarying|--out|<DIR>/out.vxtv|--input")
voxref_bad_input(raw.empty MAKE "${raw_make}|truncate:0" COMMAND "${leb_encode}|<DIR>/bad.raw|--dims|32|32|16" NEEDS bi_volume
  EXPECT "volume file <DIR>/bad\\.raw holds 0 bytes; the dimensions need 16384")
voxref_bad_input(raw.one_byte_short MAKE "${raw_make}|truncate:-1" COMMAND "${tv_encode}|<DIR>/bad.raw|--dims|32|32|16" NEEDS bi_volume
  PRE "out.vxtv" EXPECT "volume file <DIR>/bad\\.raw holds 16383 bytes; the dimensions need 16384")
voxref_bad_input(raw.one_byte_long MAKE "${raw_make}|append:x" COMMAND "${leb_encode}|<DIR>/bad.raw|--dims|32|32|16" NEEDS bi_volume
  PRE "out.vxleb" EXPECT "volume file <DIR>/bad\\.raw holds more than 16384 bytes; the dimensions need 16384")
voxref_bad_input(raw.uint16_odd_length MAKE "${raw_make}|truncate:-1" COMMAND "${leb_encode}|<DIR>/bad.raw|--dims|32|16|16|--type|uint16" NEEDS bi_volume
  EXPECT "volume file <DIR>/bad\\.raw holds 16383 bytes; the dimensions need 16384")
voxref_bad_input(raw.dims_do_not_match_fixtures MAKE "${raw_make}" NEEDS bi_volume
  COMMAND "${voxref_bin}|fixtures|generate|--dir|<DIR>/fx|--volume|<DIR>/bad.raw|--dims|32|32|17|--isovalue|100"
  EXPECT "volume file <DIR>/bad\\.raw holds 16384 bytes; the dimensions need 17408")
voxref_bad_input(raw.dims_zero MAKE "${raw_make}" COMMAND "${leb_encode}|<DIR>/bad.raw|--dims|0|32|16" NEEDS bi_volume
  EXPECT "volume file <DIR>/bad\\.raw: the dimensions are out of range: [^\n]*extent 0 is not positive")
voxref_bad_input(raw.timevarying_dims_beyond_the_container MAKE "${raw_make}" COMMAND "${tv_encode}|<DIR>/bad.raw|--dims|1024|16|1" NEEDS bi_volume
  EXPECT "--dims 1024x16x1: extent 1024 exceeds 512")
voxref_bad_input(raw.input_is_a_directory MKDIRS "adir.raw" COMMAND "${leb_encode}|<DIR>/adir.raw|--dims|32|32|16" NEEDS bi_volume
  EXPECT "volume file <DIR>/adir\\.raw is not a regular file")
voxref_bad_input(gz.truncated MAKE "${gz_make}|truncate:-30" COMMAND "${leb_encode}|<DIR>/bad.raw.gz|--dims|32|32|16" NEEDS bi_volume_gz
  EXPECT "volume file <DIR>/bad\\.raw\\.gz is a truncated gzip stream: the file ends after [0-9]+ bytes of data, before the gzip trailer[^\n]*the dimensions need 16384")
voxref_bad_input(gz.no_trailer MAKE "${gz_make}|truncate:-4" COMMAND "${leb_encode}|<DIR>/bad.raw.gz|--dims|32|32|16" NEEDS bi_volume_gz
  EXPECT "volume file <DIR>/bad\\.raw\\.gz is a truncated gzip stream: the file ends after 16384 bytes of data, before the gzip trailer")
voxref_bad_input(gz.checksum_mismatch MAKE "${gz_make}|flip:-8" COMMAND "${leb_encode}|<DIR>/bad.raw.gz|--dims|32|32|16" NEEDS bi_volume_gz
  EXPECT "volume file <DIR>/bad\\.raw\\.gz is corrupt at byte [0-9]+ of its gzip stream[^\n]*CRC-32[^\n]*does not match")
voxref_bad_input(gz.corrupt_header MAKE "${gz_make}|u8:2=7" COMMAND "${leb_encode}|<DIR>/bad.raw.gz|--dims|32|32|16" NEEDS bi_volume_gz
  EXPECT "volume file <DIR>/bad\\.raw\\.gz is corrupt at byte [0-9]+ of its gzip stream, after 0 bytes of data: [^\n]*compression method")
# Resource limits: dimensions of 65535^3 (beyond 2^40 voxels), of 10000^3 (within it: a terabyte
# claimed over 16 KB), and a gzip that expands to 2 GiB for dimensions that need 16 KB.
voxref_bad_input(raw.dims_65535_cubed MAKE "${raw_make}" COMMAND "${leb_encode}|<DIR>/bad.raw|--dims|65535|65535|65535" ULIMIT_V 1000000 NEEDS bi_volume
  EXPECT "volume file <DIR>/bad\\.raw: the dimensions are out of range: volume of 65535x65535x65535 samples exceeds the limit of 1099511627776")
voxref_bad_input(raw.dims_claim_a_terabyte MAKE "${raw_make}" COMMAND "${tv_encode}|<DIR>/bad.raw|--dims|10000|10000|10000" ULIMIT_V 1000000 NEEDS bi_volume
  EXPECT "volume file <DIR>/bad\\.raw holds 16384 bytes; the dimensions need 1000000000000")
voxref_bad_input(gz.expands_beyond_the_dims MAKE "${mbi}|<GOOD>/bomb.raw.gz|<DIR>/bomb.raw.gz" COMMAND "${leb_encode}|<DIR>/bomb.raw.gz|--dims|32|32|16"
  ULIMIT_V 1000000 NEEDS bi_bomb EXPECT "volume file <DIR>/bomb\\.raw\\.gz holds more than 16384 bytes; the dimensions need 16384")

# --- Scene JSON of the sparse-grid system (conformance/modules/sparsegrid/SCENE.md) through `voxref render`.
set(sg_make "${mbi}|${bi}/scenes/sparsegrid.json|<DIR>/bad.json")
set(render_run "${voxref_bin}|render|--scene|<DIR>/bad.json|--out|<DIR>/out.exr")
voxref_bad_input(scene_sparsegrid.empty MAKE "${sg_make}|truncate:0" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene file <DIR>/bad\\.json is not valid JSON: [^\n]*line 1, column [0-9]+")
voxref_bad_input(scene_sparsegrid.truncated MAKE "${sg_make}|truncate:40" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid PRE "out.exr"
  EXPECT "scene file <DIR>/bad\\.json is not valid JSON: [^\n]*line 1, column [0-9]+")
voxref_bad_input(scene_sparsegrid.not_an_object MAKE "${sg_make}|text:[1, 2]" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: [^\n]*expected an object")
voxref_bad_input(scene_sparsegrid.system_not_a_string MAKE "${sg_make}|json:/system=5" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: system: expected a string, got 5")
voxref_bad_input(scene_sparsegrid.level_wrong_type MAKE "${sg_make}|json:/level=\"3\"" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: level: expected an integer, got \"3\"")
voxref_bad_input(scene_sparsegrid.unknown_key MAKE "${sg_make}|json:/levle=3" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: levle: unknown key")
voxref_bad_input(scene_sparsegrid.max_extent_out_of_range MAKE "${sg_make}|json:/texture={\"max_extent\": 2}" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: texture\\.max_extent: 2 is outside 3\\.\\.16384")
voxref_bad_input(scene_sparsegrid.format_not_known MAKE "${sg_make}|json:/texture={\"format\": \"r9\"}" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: texture\\.format: 'r9' is not one of r8, rgba8, r16, r16f, r32f")
voxref_bad_input(scene_sparsegrid.dims_too_few MAKE "${sg_make}|json:/data/dims=[32, 32]" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: data\\.dims: expected 3 extents of at least 2")
voxref_bad_input(scene_sparsegrid.volume_uint16 MAKE "${sg_make}|json:/data/type=\"uint16\"" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: data\\.type: only uint8")
voxref_bad_input(scene_sparsegrid.pass_order_not_a_permutation MAKE "${sg_make}|json:/pass_order=[99]" COMMAND "${render_run}" NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: pass_order: expected a permutation of 0\\.\\.")
voxref_bad_input(scene_sparsegrid.camera_not_float32_exact
  MAKE "${sg_make}|json:/camera={\"origin\": [0, 0, 0], \"dx\": [0.3, 0, 0], \"dy\": [0, 0.25, 0], \"dz\": [0, 0, 0.25]}" COMMAND "${render_run}"
  NEEDS bi_scene_sparsegrid EXPECT "scene <DIR>/bad\\.json: camera: [^\n]*dx is not a multiple of 2\\^-21")
voxref_bad_input(scene_sparsegrid.volume_is_a_truncated_gzip MAKE "${sg_make}|json:/data/volume=\"<DIR>/bad.raw.gz\"" MAKE2 "${gz_make}|truncate:-30"
  COMMAND "${render_run}" NEEDS "bi_scene_sparsegrid;bi_volume_gz"
  EXPECT "scene <DIR>/bad\\.json: data\\.volume: volume file <DIR>/bad\\.raw\\.gz is a truncated gzip stream")
voxref_bad_input(scene_sparsegrid.volume_dims_65535_cubed MAKE "${sg_make}|json:/data/dims=[65535, 65535, 65535]" COMMAND "${render_run}"
  ULIMIT_V 1000000 NEEDS bi_scene_sparsegrid
  EXPECT "scene <DIR>/bad\\.json: data\\.volume: volume file [^\n]*step_000\\.rgba: the dimensions are out of range: volume of 65535x65535x65535 samples exceeds")

# --- Scene JSON of the time-varying system (conformance/modules/timevarying/timevarying_scene.h).
set(tvs_make "${mbi}|${bi}/scenes/timevarying.json|<DIR>/bad.json")
voxref_bad_input(scene_timevarying.side_not_a_power_of_two MAKE "${tvs_make}|json:/side=12" COMMAND "${render_run}" NEEDS bi_scene_timevarying
  EXPECT "scene <DIR>/bad\\.json: side: expected a power of two")
voxref_bad_input(scene_timevarying.side_wrong_type MAKE "${tvs_make}|json:/side=\"16\"" COMMAND "${render_run}" NEEDS bi_scene_timevarying PRE "out.exr"
  EXPECT "scene <DIR>/bad\\.json: side: expected an integer, got \"16\"")
voxref_bad_input(scene_timevarying.steps_out_of_range MAKE "${tvs_make}|json:/steps=100000" COMMAND "${render_run}" NEEDS bi_scene_timevarying
  EXPECT "scene <DIR>/bad\\.json: steps: 100000 is outside 1\\.\\.4096")
voxref_bad_input(scene_timevarying.unknown_key MAKE "${tvs_make}|json:/bogus=1" COMMAND "${render_run}" NEEDS bi_scene_timevarying
  EXPECT "scene <DIR>/bad\\.json: bogus: unknown key")
voxref_bad_input(scene_timevarying.data_not_known MAKE "${tvs_make}|json:/data=\"teapot\"" COMMAND "${render_run}" NEEDS bi_scene_timevarying
  EXPECT "scene <DIR>/bad\\.json: data: 'teapot' is not one of ")
voxref_bad_input(scene_timevarying.only_steps_out_of_range MAKE "${tvs_make}|json:/only_steps=[5]" COMMAND "${render_run}" NEEDS bi_scene_timevarying
  EXPECT "scene <DIR>/bad\\.json: only_steps: 5 is outside 0\\.\\.1")

# --- The fixture manifest and the isosurface scenes in it (conformance/modules/iso/iso_fixtures.h,
# iso_scene.h) through `voxref fixtures verify`; its scratch folder goes to TMPDIR=<DIR>/tmp, which
# must be empty again afterwards.
set(fx_make "${mbi}|<GOOD>/fx/manifest.json|<DIR>/fx/manifest.json")
set(fx_run "${voxref_bin}|fixtures|verify|--dir|<DIR>/fx")
set(fx_env "TMPDIR=<DIR>/tmp")
function(bi_manifest name)
  voxref_bad_input(${name} ${ARGN} COMMAND "${fx_run}" MKDIRS "fx|tmp" ENVIRONMENT "${fx_env}" NEEDS bi_fixtures)
endfunction()
bi_manifest(manifest.empty MAKE "${fx_make}|truncate:0" EXPECT "<DIR>/fx/manifest\\.json: [^\n]*line 1, column [0-9]+")
bi_manifest(manifest.truncated MAKE "${fx_make}|truncate:200" EXPECT "<DIR>/fx/manifest\\.json: [^\n]*line [0-9]+, column [0-9]+")
bi_manifest(manifest.not_an_object MAKE "${fx_make}|text:[]" EXPECT "<DIR>/fx/manifest\\.json: expected a JSON object")
bi_manifest(manifest.scenes_wrong_type MAKE "${fx_make}|json:/scenes=5" EXPECT "<DIR>/fx/manifest\\.json: scenes: expected an array")
bi_manifest(manifest.sha256_malformed MAKE "${fx_make}|json:/files/0/sha256=\"abc\""
  EXPECT "<DIR>/fx/manifest\\.json: files\\[0\\]\\.sha256: expected 64 lowercase hexadecimal digits")
bi_manifest(manifest.path_outside_the_folder MAKE "${fx_make}|json:/files/0/path=\"/etc/passwd\""
  EXPECT "<DIR>/fx/manifest\\.json: files\\[0\\]\\.path: '/etc/passwd' is not a relative path inside the fixture directory")
bi_manifest(scene_iso.name_missing MAKE "${fx_make}|json-remove:/scenes/0/name"
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.name: missing")
bi_manifest(scene_iso.unknown_key MAKE "${fx_make}|json:/scenes/0/colour=\"red\""
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.colour: unknown key")
bi_manifest(scene_iso.name_escapes_the_folder MAKE "${fx_make}|json:/scenes/0/name=\"../x\""
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.name: '\\.\\./x' is not a plain file name")
bi_manifest(scene_iso.isovalue_wrong_type MAKE "${fx_make}|json:/scenes/0/isovalue=\"85\""
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.isovalue: expected a number, got \"85\"")
bi_manifest(scene_iso.dims_out_of_range MAKE "${fx_make}|json:/scenes/0/dims=[65535, 65535, 65535]"
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.dims\\[0\\]: 65535 is outside 1\\.\\.1025")
bi_manifest(scene_iso.frames_zero MAKE "${fx_make}|json:/scenes/0/orbit/frames=0"
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.orbit\\.frames: 0 is outside 1\\.\\.")
bi_manifest(scene_iso.data_not_known MAKE "${fx_make}|json:/scenes/0/data=\"teapot\""
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.data: [^\n]*'teapot'")
bi_manifest(scene_iso.field_of_view_out_of_range MAKE "${fx_make}|json:/scenes/0/camera/fov_y_deg=-5"
  EXPECT "<DIR>/fx/manifest\\.json: scenes\\[0\\]\\.camera: fov_y must be in \\(0, 180\\)")
bi_manifest(scene_iso.volume_file_missing MAKE "${fx_make}|json:/scenes/0/volume_file=\"<DIR>/none.raw\""
  EXPECT "<DIR>/fx/manifest\\.json: [^\n]*volume file <DIR>/none\\.raw does not exist")

# --- A baseline results.json (conformance/framework/report/results_reader.h) through `voxref conform
# --baseline`: the report folder, which holds an earlier results.json, must be left as it was.
set(rs_make "${mbi}|<GOOD>/report/results.json|<DIR>/bad.json")
set(rs_run "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|<DIR>/report|--baseline|<DIR>/bad.json")
function(bi_results name)
  voxref_bad_input(${name} ${ARGN} COMMAND "${rs_run}" PRE "report/results.json" NEEDS bi_report)
endfunction()
bi_results(results.empty MAKE "${rs_make}|truncate:0" EXPECT "--baseline: <DIR>/bad\\.json: [^\n]*line 1, column [0-9]+")
bi_results(results.truncated MAKE "${rs_make}|truncate:100" EXPECT "--baseline: <DIR>/bad\\.json: [^\n]*line [0-9]+, column [0-9]+")
bi_results(results.format_wrong_type MAKE "${rs_make}|json:/format=5"
  EXPECT "--baseline: <DIR>/bad\\.json: not a voxref results file \\(\"format\" is not \"voxref-results\"\\)")
bi_results(results.unsupported_version MAKE "${rs_make}|json:/format_version=2"
  EXPECT "--baseline: <DIR>/bad\\.json: [^\n]*version 2[^\n]*version 1")
bi_results(results.cases_wrong_type MAKE "${rs_make}|json:/cases=5" EXPECT "--baseline: <DIR>/bad\\.json[.:] ?cases: expected an array")
bi_results(results.status_not_known MAKE "${rs_make}|json:/cases/0/status=\"bogus\""
  EXPECT "--baseline: <DIR>/bad\\.json: cases\\[0\\]: [^\n]*\\.status: not one of pass, warn, fail, skip, crash, timeout")
bi_results(results.id_missing MAKE "${rs_make}|json-remove:/cases/0/id" EXPECT "--baseline: <DIR>/bad\\.json: cases\\[0\\]: [^\n]*id: missing")
bi_results(results.seconds_wrong_type MAKE "${rs_make}|json:/cases/0/seconds_gl=\"slow\""
  EXPECT "--baseline: <DIR>/bad\\.json: cases\\[0\\]: [^\n]*seconds_gl: expected a number")
bi_results(results.allowed_wrong_type
  MAKE "${rs_make}|json:/cases/0/worst_pixels=[{\"x\": 1, \"y\": 1, \"k\": 0, \"oracle\": \"exact\", \"gl\": 1, \"emulated\": 1, \"reference\": 1, \"allowed\": [\"low\", 2]}]"
  EXPECT "--baseline: <DIR>/bad\\.json: cases\\[0\\]: [^\n]*worst_pixels\\.allowed: expected[^\n]*number")
bi_results(results.missing EXPECT "--baseline: <DIR>/bad\\.json does not exist")

# --- The shader of `voxref check-shader` (docs/shader-interface.md): the report folder must not
# appear. The good shader is the built-in stage itself.
set(shader_make "${mbi}|${PROJECT_SOURCE_DIR}/gpu/shaders/combination.frag|<DIR>/bad.frag")
set(shader_run "${voxref_bin}|check-shader|--case|sparsegrid.combination.rgba8.l3.xray|--shader|<DIR>/bad.frag|--out|<DIR>/report")
voxref_bad_input(shader.empty MAKE "${shader_make}|truncate:0" COMMAND "${shader_run}"
  EXPECT "<DIR>/bad\\.frag does not build as stage `combination`[^\n]*\n[^\n]*main")
voxref_bad_input(shader.truncated MAKE "${shader_make}|truncate:-40" COMMAND "${shader_run}"
  EXPECT "<DIR>/bad\\.frag does not build as stage `combination`[^\n]*\n0:[0-9]+\\([0-9]+\\): [^\n]*error")
# GLSL 4.50 section 3.1: the source is UTF-8 text. Bytes 0xd0 at the start; a NUL byte at offset
# 170, on the shader's second line (its first line, a comment, has fewer than 170 bytes).
voxref_bad_input(shader.binary MAKE "${shader_make}|flip:0|flip:1|flip:2|flip:3" COMMAND "${shader_run}"
  EXPECT "<DIR>/bad\\.frag: byte 0 \\(line 1, column 1\\): 0xd0 is not UTF-8 text")
voxref_bad_input(shader.nul_byte MAKE "${shader_make}|u8:170=0" COMMAND "${shader_run}"
  EXPECT "<DIR>/bad\\.frag: byte 170 \\(line 2, column [0-9]+\\): 0x00 \\(NUL\\) is not UTF-8 text")
voxref_bad_input(shader.is_a_directory MKDIRS "bad.frag" COMMAND "${shader_run}" EXPECT "<DIR>/bad\\.frag is not a regular file")

# --- Bad options: outputs that cannot be written, sizes beyond the formats' limits.
set(plume_encode "${voxref_bin}|encode|--codec|timevarying|--plume|--side|16|--steps|2|--out")
voxref_bad_input(option.out_in_a_missing_folder COMMAND "${plume_encode}|<DIR>/no-such-folder/out.vxtv"
  EXPECT "cannot write <DIR>/no-such-folder/out\\.vxtv: [^\n]*No such file or directory")
voxref_bad_input(option.out_under_a_regular_file COMMAND "${plume_encode}|<DIR>/file/out.vxtv" PRE "file"
  EXPECT "cannot write <DIR>/file/out\\.vxtv: [^\n]*Not a directory")
voxref_bad_input(option.out_in_an_unwritable_folder COMMAND "${plume_encode}|<DIR>/readonly/out.vxtv" UNWRITABLE "readonly"
  EXPECT "cannot write <DIR>/readonly/out\\.vxtv: [^\n]*Permission denied")
voxref_bad_input(option.out_is_a_folder COMMAND "${plume_encode}|<DIR>/out.vxtv" MKDIRS "out.vxtv"
  EXPECT "cannot write <DIR>/out\\.vxtv: it is a directory")
voxref_bad_input(option.bounds_out_unwritable_leaves_no_stream MAKE "${mbi}|<GOOD>/volume.raw.gz|<DIR>/volume.raw.gz" NEEDS bi_volume_gz
  COMMAND "${voxref_bin}|encode|--codec|leb|--input|<DIR>/volume.raw.gz|--dims|32|32|16|--out|<DIR>/out.vxleb|--bounds-out|<DIR>/readonly/out.vxlbb"
  UNWRITABLE "readonly" EXPECT "cannot write <DIR>/readonly/out\\.vxlbb: [^\n]*Permission denied")
voxref_bad_input(option.decode_out_in_a_missing_folder_leaves_no_gradients MAKE "${mbi}|<GOOD>/volume.vxleb|<DIR>/volume.vxleb" NEEDS bi_leb
  COMMAND "${leb_decode}|<DIR>/volume.vxleb|--out|<DIR>/no-such-folder/volume.raw|--gradients-out|<DIR>/volume.grad" PRE "volume.grad"
  EXPECT "cannot write <DIR>/no-such-folder/volume\\.raw: [^\n]*No such file or directory")
voxref_bad_input(option.decode_out_is_a_folder MAKE "${mbi}|<GOOD>/volume.vxleb|<DIR>/volume.vxleb" NEEDS bi_leb
  COMMAND "${leb_decode}|<DIR>/volume.vxleb|--out|<DIR>/volume.raw|--gradients-out|<DIR>/volume.grad" MKDIRS "volume.raw"
  EXPECT "cannot write <DIR>/volume\\.raw: it is a directory")
voxref_bad_input(option.conform_out_is_a_regular_file COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|<DIR>/report" PRE "report"
  EXPECT "cannot create directory <DIR>/report")
voxref_bad_input(option.conform_out_in_an_unwritable_folder COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|<DIR>/readonly/report"
  UNWRITABLE "readonly" EXPECT "cannot create directory <DIR>/readonly/report: Permission denied")
voxref_bad_input(option.render_out_under_a_regular_file COMMAND "${voxref_bin}|render|--scene|sparsegrid.hard.level1|--out|<DIR>/file/out.exr" PRE "file"
  EXPECT "cannot write <DIR>/file/out\\.exr")
# Options of `fixtures generate` refused when parsed, naming the option; nothing written.
foreach(v nan inf -inf 1e309)
  string(REPLACE "-" "minus_" entry "${v}")
  voxref_bad_input(option.fixtures_isovalue_${entry} COMMAND "${voxref_bin}|fixtures|generate|--dir|<DIR>/fx|--scene|blobs_not_a_cube|--frames|1|--isovalue|${v}"
    EXPECT "--isovalue: expected a finite number, got '${v}'")
endforeach()
foreach(n -3 0 100000)
  string(REPLACE "-" "minus_" entry "${n}")
  voxref_bad_input(option.fixtures_frames_${entry} COMMAND "${voxref_bin}|fixtures|generate|--dir|<DIR>/fx|--scene|blobs_not_a_cube|--frames|${n}"
    EXPECT "--frames: Value ${n} not in range 1 to 10000")
endforeach()
voxref_bad_input(option.fixtures_dir_is_a_regular_file COMMAND "${voxref_bin}|fixtures|generate|--dir|<DIR>/fx|--scene|blobs_not_a_cube|--frames|1"
  PRE "fx" EXPECT "cannot create directory <DIR>/fx")
# Resource limits on options: a plume larger than the container holds is refused before it is made.
voxref_bad_input(option.plume_side_beyond_the_container COMMAND "${voxref_bin}|encode|--codec|timevarying|--plume|--side|4096|--steps|2|--out|<DIR>/out.vxtv"
  ULIMIT_V 1000000 EXPECT "--side 4096: expected a power of two in 8\\.\\.512")
voxref_bad_input(option.plume_steps_beyond_the_container COMMAND "${voxref_bin}|encode|--codec|timevarying|--plume|--side|64|--steps|100000000|--out|<DIR>/out.vxtv"
  ULIMIT_V 1000000 EXPECT "--steps 100000000: expected 1\\.\\.65536")

# Outputs that are not regular files (a device, a FIFO, a socket, a symbolic link) are never
# replaced: written through, or refused (tests/cli/special_outputs.sh, docs/bad_input.md).
foreach(kind character_device fifo socket symlink)
  add_test(NAME badinput.output_not_a_regular_file.${kind}
           COMMAND sh "${CMAKE_CURRENT_SOURCE_DIR}/cli/special_outputs.sh" ${kind} "${voxref_bin}" "${mbi}" "${good}/volume.vxleb" "${bi}/t/special_${kind}")
  set_tests_properties(badinput.output_not_a_regular_file.${kind} PROPERTIES LABELS "badinput;cli;sanitize" TIMEOUT 120 FIXTURES_REQUIRED bi_leb
                       SKIP_REGULAR_EXPRESSION "VOXREF_TEST_SKIPPED:" FAIL_REGULAR_EXPRESSION "FAIL:")
endforeach()

# A run ended by SIGINT or SIGTERM removes its temporary files; SIGKILL, which no process can
# handle, is the control that shows they existed (tests/cli/killed_outputs.sh).
foreach(kind decode_sigterm encode_sigint decode_sigkill)
  add_test(NAME badinput.killed_run_leaves_no_temporaries.${kind}
           COMMAND sh "${CMAKE_CURRENT_SOURCE_DIR}/cli/killed_outputs.sh" ${kind} "${voxref_bin}" "${good}/volume.vxleb" "${good}/volume.raw.gz" "${bi}/t/killed_${kind}")
  set_tests_properties(badinput.killed_run_leaves_no_temporaries.${kind} PROPERTIES LABELS "badinput;cli;sanitize" TIMEOUT 120 FIXTURES_REQUIRED bi_leb
                       FAIL_REGULAR_EXPRESSION "FAIL:")
endforeach()
