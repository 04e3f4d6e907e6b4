#!/usr/bin/python3
"""ctest tools.MakeBench.RunsTheBenchmarkProgramsOnlyAndFailsWithThem: `make bench` runs
every program build/bench/bench_* and fails when one fails. Before, it ran every entry of
build/bench/ (CMakeFiles/, Makefile, CTestTestfile.cmake, cmake_install.cmake): four
"Permission denied" lines and exit status 2 (make's Error 126) after benchmarks that had
all run, while a benchmark that failed before the last entry went unnoticed. Checked on a
stand-in build folder (`make -o build`: nothing is configured or built): two programs
that print their argument, one that fails, and CMake's files beside them."""
import os
import subprocess
import sys

from tool_test_args import arguments

a, work = arguments("source", "work")
bench = os.path.join(work, "bench")
os.makedirs(os.path.join(bench, "CMakeFiles"))
for name in ("Makefile", "CTestTestfile.cmake", "cmake_install.cmake"):
    open(os.path.join(bench, name), "w").close()


def program(name, status):
    path = os.path.join(bench, name)
    with open(path, "w") as f:
        f.write(f'#!/bin/sh\necho "{name} ran with $1"\nexit {status}\n')
    os.chmod(path, 0o755)


def make_bench():
    return subprocess.run(["make", "-C", a.source, "--no-print-directory", "-o", "build", f"BUILD={work}",
                           "bench"], capture_output=True, text=True)


failures = []
program("bench_a", 0)
program("bench_b", 0)
r = make_bench()
print(r.returncode, r.stdout[-600:], r.stderr[-600:])
if r.returncode != 0:
    failures.append(f"make bench with two good programs: exit {r.returncode}:\n{r.stderr[-600:]}")
if "Permission denied" in r.stderr or "CMakeFiles" in r.stdout:
    failures.append(f"make bench ran CMake's files:\n{r.stdout[-600:]}{r.stderr[-600:]}")
for name in ("bench_a", "bench_b"):
    if f"{name} ran with --benchmark_min_time=0.2" not in r.stdout:
        failures.append(f"make bench did not run {name}:\n{r.stdout[-600:]}")

program("bench_a", 1)  # a failing benchmark before the last one
r = make_bench()
print(r.returncode, r.stdout[-600:], r.stderr[-600:])
if r.returncode == 0:
    failures.append(f"make bench with a failing program exited 0:\n{r.stdout[-600:]}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
