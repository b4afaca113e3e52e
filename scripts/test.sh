#!/usr/bin/env bash
# The README's second command: install what is missing, build, run every test through ctest.
#  1. a sim-only build (no GL, no libav: proves the simulation library stands alone), under
#     AddressSanitizer + UBSan with the heavy invariant checks on, running the unit tests, one
#     process per test file (COLLIDE_TESTS_BY_FILE: starting a sanitized process costs about
#     0.2 s of CPU, more than most test cases; the full build's ctest lists them one by one);
#  2. the full sanitizer build, running the other modules' `unit` tests and the CLI option matrix
#     (label `cli-matrix`: the sanitized `collide` over many bad and extreme option sets, so that
#     UBSan, which never recovers here, checks the command line's paths, not just the libraries);
#     not the renderer suite's second pass on EGL: under the sanitizers it repeats our code, whose
#     EGL context the renderer's own EGL test cases already run (step 3 runs its cases on EGL);
#     one process per test file too (COLLIDE_TESTS_BY_FILE, as in step 1), less the test cases
#     in the doctest suite `sweep` (the same checks and code as other cases of their file, over
#     many more parameters: step 5 runs them);
#  3. a renderer-only build without OSMesa (COLLIDE_WITH_OSMESA=OFF: EGL only, as on distributions
#     whose Mesa has no OSMesa), running the renderer tests on EGL, one process per test file
#     (COLLIDE_TESTS_BY_FILE: a process that loads Mesa's EGL and LLVM costs about 0.5 s to
#     start), but not the files labelled `layout-only` (they read what was laid out, never a
#     pixel: the backend cannot change it; steps 2 and 5 run them);
#  4. a lean build without libav (COLLIDE_VIDEO=OFF: the drawing program for CI thumbnails), only
#     the programs and their own suite (label `lean`: thumbnail, compare, PNG frames, a video
#     refused with exit 2);
#  5. the full RelWithDebInfo build, running the whole suite, including the long physics runs
#     (label `slow`) and the end-to-end CLI tests (label `e2e`), but not the option matrix
#     (label `cli-matrix`: step 2 ran it against the sanitized `collide`, which checks more)
#     nor the renderer suite's second pass on EGL (step 3 ran every
#     renderer test case on EGL, in the same RelWithDebInfo build but for OSMesa, which only the
#     choice of backend reads; this build's own EGL cases, 'EGL surfaceless gives the same pixels
#     as OSMesa' and `thumbnail --gl`, run EGL beside OSMesa; about 45 s); ctest's summary line
#     comes last.
# With CI=true warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh --test
common=(-G Ninja -DCOLLIDE_BUILD_BENCH=OFF)
if [[ "${CI:-}" == "true" ]]; then
    common+=(-DCOLLIDE_WERROR=ON)
fi
jobs=$(nproc)

echo "==> [1/5] sim-only build with sanitizers (build/sim-asan)"
cmake -S . -B build/sim-asan "${common[@]}" -DCMAKE_BUILD_TYPE=Debug -DCOLLIDE_SIM_ONLY=ON \
      -DCOLLIDE_SANITIZE=ON -DCOLLIDE_VALIDATE=ON -DCOLLIDE_TESTS_BY_FILE=ON >/dev/null
cmake --build build/sim-asan -j "$jobs"
ctest --test-dir build/sim-asan -L unit --output-on-failure -j "$jobs"

echo "==> [2/5] full build with sanitizers (build/asan)"
cmake -S . -B build/asan "${common[@]}" -DCMAKE_BUILD_TYPE=Debug -DCOLLIDE_SANITIZE=ON \
      -DCOLLIDE_TESTS_BY_FILE=ON >/dev/null
cmake --build build/asan -j "$jobs"
ctest --test-dir build/asan -L 'unit|cli-matrix' \
      -E "^collide_(sim|show)_tests:|^collide_render_tests:egl: " --output-on-failure -j "$jobs"

echo "==> [3/5] renderer without OSMesa (build/no-osmesa)"
cmake -S . -B build/no-osmesa "${common[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCOLLIDE_WITH_OSMESA=OFF -DCOLLIDE_TESTS_BY_FILE=ON >/dev/null
cmake --build build/no-osmesa -j "$jobs" --target collide_render_tests
ctest --test-dir build/no-osmesa -R "^collide_render_tests:" -LE layout-only --output-on-failure \
      -j "$jobs"

echo "==> [4/5] lean build without libav (build/lean)"
cmake -S . -B build/lean "${common[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE_VIDEO=OFF \
      >/dev/null
cmake --build build/lean -j "$jobs" --target collide_lean_tests
ctest --test-dir build/lean -L lean --output-on-failure -j "$jobs"

echo "==> [5/5] full build (build/test), every test but the option matrix (step 2 ran it)" \
     "and the renderer's EGL pass (step 3 ran it)"
cmake -S . -B build/test "${common[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build/test -j "$jobs"
ctest --test-dir build/test -LE cli-matrix -E "^collide_render_tests:egl: " --output-on-failure \
      -j "$jobs"
