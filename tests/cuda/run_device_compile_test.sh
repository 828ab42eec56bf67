#!/usr/bin/env bash
# The per-cell headers as CUDA device code (tests/cuda/device_kernels.cu), in two steps:
#   compile   nvcc (from PATH, or /usr/local/cuda/bin) compiles the kernels with every warning an
#             error; passes when they compile
#   run       runs them on the GPU and compares with the host; passes only when the kernels ran
#             and agreed (compiling first if the compile step has not)
# Either step is skipped (exit 77, ctest's SKIP_RETURN_CODE), saying why, without nvcc; the run
# step is also skipped without a CUDA device (the program exits 77 then).
# Usage: run_device_compile_test.sh compile|run <fluidbed source dir> <scratch dir>
set -euo pipefail
step=$1
source_dir=$(cd "$2" && pwd)
work=$3
nvcc=$(command -v nvcc || true)
[ -n "$nvcc" ] || { [ -x /usr/local/cuda/bin/nvcc ] && nvcc=/usr/local/cuda/bin/nvcc; }
if [ -z "$nvcc" ]; then
  echo "skipped: no nvcc in PATH or /usr/local/cuda/bin, so the CUDA device code cannot be compiled"
  exit 77
fi
mkdir -p "$work"
program="$work/device_kernels"
if [ "$step" = compile ] || [ ! -x "$program" ]; then
  "$nvcc" --version | tail -n 2
  # Eigen 3.4 writes __host__ __device__ on defaulted special members, which nvcc reports as
  # ignored (diagnostic 20012) in Eigen's own headers; every other warning is an error.
  # sm_80 code plus compute_80 PTX: runs natively on A100 and is JIT-compiled for newer GPUs.
  flags=(-std=c++20 --expt-relaxed-constexpr -arch=sm_80 -I"$source_dir/include" -isystem /usr/include/eigen3
         -diag-suppress 20012 -Werror all-warnings -Xcompiler -Wall,-Wextra)
  "$nvcc" "${flags[@]}" "$source_dir/tests/cuda/device_kernels.cu" -o "$program.new"
  # nvcc compiles some host code reached from device code (a std::string_view made from a C
  # string) to undefined behaviour without a diagnostic, and the optimizer then empties the
  # kernel: it runs and writes nothing. Every kernel of the test writes its results, so each
  # must store to global memory, in a debug build (assertions on) and a release one (NDEBUG);
  # this needs no GPU.
  for build in debug release; do
    defines=()
    [ "$build" = release ] && defines=(-DNDEBUG)
    "$nvcc" "${flags[@]}" "${defines[@]}" -ptx "$source_dir/tests/cuda/device_kernels.cu" -o "$work/kernels.ptx"
    empty=$(awk '/^[.a-z ]*\.entry /{ if (name != "" && !stores) print name; name = $NF; stores = 0 }
                 /st\.global/{ stores = 1 }
                 END { if (name != "" && !stores) print name }' "$work/kernels.ptx")
    if [ -n "$empty" ]; then
      echo "FAILED ($build build): kernels that store nothing, compiled empty:"
      echo "$empty"
      exit 1
    fi
  done
  mv "$program.new" "$program"
  echo "every closure of every registry, moment inversion, the kinetic-theory set, the elastic force, the DQMOM sources and the multi-fluid closures compiled as device code, every kernel storing its results (debug and release)"
fi
[ "$step" = compile ] && exit 0
"$program"
