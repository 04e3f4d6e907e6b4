#!/usr/bin/env bash
# Coverage-guided fuzzing of flapsim's input readers with clang's libFuzzer (`make fuzz-coverage`):
# the wing file, SVG drawing and outline CSV readers (tools/fuzz/wing_reader_fuzzer.cpp) and the
# case, chain and kinematics CSV readers (tools/fuzz/case_reader_fuzzer.cpp), each for FUZZ_SECONDS
# (default 300) of one core, with AddressSanitizer and UndefinedBehaviorSanitizer, from the shipped
# files as seeds.
# The readers' sources (wings/loader/, and pipeline/io/'s case, chain and kinematics readers) are
# compiled with clang and instrumented; the rest they call is linked from the Release build
# (BUILD, default build/), which `make fuzz-coverage` makes first. Work goes to OUT (default
# build/fuzz-coverage/): objects, the two programs, their corpora (kept between runs, so a second
# run goes on where the first stopped) and crashes/. Exit status: 0 no finding, 1 a finding
# (its input in OUT/crashes/, replayed by passing the file to the program), 2 a setup error.
# docs/reliability.md, "Coverage-guided fuzzing".
set -euo pipefail

src=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$src/build}
out=${OUT:-$build/fuzz-coverage}
seconds=${FUZZ_SECONDS:-300}
jobs=${JOBS:-2}

# clang and its libFuzzer runtime (Debian 12: clang-14, libclang-rt-14-dev), installed when missing.
need=()
command -v clang++ >/dev/null 2>&1 || need+=(clang)
dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "install ok installed" || need+=(libclang-rt-14-dev)
if [ ${#need[@]} -gt 0 ]; then
  echo "coverage_fuzz: installing ${need[*]}" >&2
  if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo); else
    echo "coverage_fuzz: need root or sudo to install: ${need[*]}" >&2
    exit 2
  fi
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}" || exit 2
fi
libs=("$build/pipeline/io/libflapsim_io.a" "$build/reduction/libflapsim_reduction.a" "$build/fem/libflapsim_fem.a"
      "$build/uvlm/libflapsim_uvlm.a" "$build/mbd/libflapsim_mbd.a")
for a in "${libs[@]}"; do
  [ -f "$a" ] || { echo "coverage_fuzz: $a missing: build first (make build)" >&2; exit 2; }
done

flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -I"$src" -I/usr/include/eigen3)
mkdir -p "$out/obj" "$out/crashes"
# 1. The readers, instrumented (compiled anew each time: a minute or two on two cores).
sources=("$src"/wings/loader/*.cpp "$src"/pipeline/io/case_file.cpp "$src"/pipeline/io/chain_file.cpp
         "$src"/pipeline/io/kinematics_csv.cpp "$src"/pipeline/io/kinematics_samples.cpp)
rm -f "$out"/obj/*.o
printf '%s\n' "${sources[@]}" | xargs -P "$jobs" -I{} sh -c '
  clang++ "$@" -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -c "{}" \
    -o "$0/obj/$(basename "{}" .cpp).o"' "$out" "${flags[@]}" ||
  { echo "coverage_fuzz: a reader did not compile with clang (above)" >&2; exit 2; }
loader_objs=("$out"/obj/*.o)
io_objs=()
wing_objs=()
for o in "${loader_objs[@]}"; do
  case $(basename "$o") in
    case_file.o | chain_file.o | kinematics_csv.o | kinematics_samples.o) io_objs+=("$o") ;;
    *) wing_objs+=("$o") ;;
  esac
done
# 2. The two programs: the instrumented readers first, the Release libraries for the rest.
san=(-fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined)
linked() { echo "coverage_fuzz: $1 did not link (above)" >&2; exit 2; }
clang++ "${flags[@]}" "${san[@]}" "$src/tools/fuzz/wing_reader_fuzzer.cpp" "${wing_objs[@]}" \
  -o "$out/wing_reader_fuzzer" || linked wing_reader_fuzzer
clang++ "${flags[@]}" "${san[@]}" "$src/tools/fuzz/case_reader_fuzzer.cpp" "${io_objs[@]}" "${wing_objs[@]}" \
  "${libs[@]}" -fopenmp -lcholmod -o "$out/case_reader_fuzzer" || linked case_reader_fuzzer
# 3. Seeds: the shipped files behind the byte that picks their reader.
seed() {  # seed DIR BYTE FILE...
  local dir=$1 byte=$2
  shift 2
  mkdir -p "$dir"
  for f in "$@"; do
    if [ -f "$f" ]; then { printf "\\x$byte"; cat "$f"; } > "$dir/seed_$(basename "$f")"; fi
  done
}
seed "$out/corpus_wing" 00 "$src"/wings/*.toml "$src"/tests/data/*wing*.toml
seed "$out/corpus_wing" 01 "$src"/tests/data/*.svg
seed "$out/corpus_case" 00 "$src"/cases/*.toml "$src"/tests/data/*case*.toml
seed "$out/corpus_case" 01 "$src"/cases/chains/*.toml
seed "$out/corpus_wing" 02 "$src"/wings/outlines/*.csv "$src"/tests/data/*outline*.csv
printf '\x02# a measured wingbeat\nphase,sweep_deg\n0,60\n0.25,0\n0.5,-60\n0.75,0\n1,60\n' > "$out/corpus_case/seed_phase.csv"
printf '\x06t_ms\tsweep_deg\n0\t60\n9.6\t0\n19.2\t-60\n28.7\t0\n38.3\t60\n47.9\t0\n' > "$out/corpus_case/seed_times.csv"
# The files the seeds name, where the readers look for them (beside OUT/fuzz.toml).
cp -r "$src/wings/outlines" "$out/"
cp "$src/tests/data/drawn_wing.svg" "$out/"
# 4. Each for the time given, one core each, side by side.
status=0
run() {  # run NAME
  (cd "$out" && "./$1" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=40000 \
    -artifact_prefix="crashes/$1-" -print_final_stats=1 "corpus_${1%%_*}" > "$1.log" 2>&1)
}
run wing_reader_fuzzer & p1=$!
run case_reader_fuzzer & p2=$!
wait $p1 || status=1
wait $p2 || status=1
for f in wing_reader_fuzzer case_reader_fuzzer; do
  runs=$(grep -m1 'stat::number_of_executed_units' "$out/$f.log" | awk '{print $2}' || true)
  echo "$f: ${runs:-?} inputs in ${seconds} s, corpus $(ls "$out/corpus_${f%%_*}" | wc -l) files; log $out/$f.log"
done
if [ $status -ne 0 ]; then
  echo "coverage_fuzz: a finding: its input is in $out/crashes/ (replay: $out/<program> <file>)" >&2
  exit 1
fi
echo "coverage_fuzz: no finding"
