#!/bin/sh
# The engine as an installed library, as another project would use it: `cmake --install` the
# already-built tree into a scratch prefix (nothing is rebuilt), then configure, build and run
# examples/ against that prefix alone, with Qt made unfindable.
#   install_test.sh CMAKE BUILD_DIR SOURCE_DIR SCRATCH_DIR [GENERATOR]
set -eu
cmake_command="$1"; build_dir="$2"; source_dir="$3"; scratch="$4"; generator="${5:-}"
prefix="$scratch/prefix"
rm -rf "$scratch"
mkdir -p "$scratch"

"$cmake_command" --install "$build_dir" --prefix "$prefix" >"$scratch/install.log"

# Every header of the engine is installed, under include/impetus/ as it lies under src/: a header
# missing from a target's source list would be missed by a program that includes it.
(cd "$source_dir/src" && find model controller -name '*.h' | sort) >"$scratch/source-headers"
(cd "$prefix/include/impetus" && find . -name '*.h' | sed 's|^\./||' | sort) >"$scratch/installed-headers"
if ! diff -u "$scratch/source-headers" "$scratch/installed-headers"; then
  echo "installed headers differ from the engine's headers (- source, + installed)" >&2
  exit 1
fi

# The package configures with no Qt anywhere: CMAKE_DISABLE_FIND_PACKAGE_Qt6 makes any
# find_package(Qt6) fail. CMAKE_PREFIX_PATH is the scratch prefix alone.
set -- --no-warn-unused-cli -S "$source_dir/examples" -B "$scratch/examples" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_DISABLE_FIND_PACKAGE_Qt6=ON -DCMAKE_BUILD_TYPE=Release
if [ -n "$generator" ]; then set -- "$@" -G "$generator"; fi
"$cmake_command" "$@" >"$scratch/configure.log" || { cat "$scratch/configure.log" >&2; exit 1; }
"$cmake_command" --build "$scratch/examples" >"$scratch/build.log" || { cat "$scratch/build.log" >&2; exit 1; }

if ldd "$scratch/examples/falling_ball" | grep -i qt; then
  echo "the example links Qt" >&2
  exit 1
fi
# The example exits 0 only when the engine's fall time agrees with sqrt(2h/g) to one time step.
"$scratch/examples/falling_ball" 2.0
"$scratch/examples/falling_ball" 0.5
