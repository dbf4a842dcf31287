#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install test, in two phases:
#   prepare: installs the main build into a fresh prefix and builds the out-of-tree plugins of
#            external_plugin/ and examples/ForceFieldPlugin against it with find_package(Stroma)
#            (a build step: tests/tooling/prepare.sh runs it before ctest, with no time limit);
#   check:   (the ctest tooling_install) checks that the INSTALLED stroma lists and runs the
#            plugin's component (found through STROMA_PLUGIN_PATH) and finds its own built-in
#            plugins and libraries in the install prefix, not in the build tree, and that the
#            example force field reaches its analytic static equilibrium.
#
# Usage: install_test.sh prepare|check MAIN_BUILD_DIR WORK_DIR   (prepare wipes WORK_DIR)
set -euo pipefail

phase=$1
build_dir=$(cd "$2" && pwd)
work=$3
here=$(cd "$(dirname "$0")" && pwd)
cmake=${CMAKE_COMMAND:-cmake}

fail() {
  echo "install_test: FAIL: $*" >&2
  exit 1
}
# Runs a command, saving its stdout+stderr in $work/<name>.log; fails when the exit code differs
# from the expected one.
expect() {
  local name=$1 code=$2
  shift 2
  local rc=0
  "$@" >"$work/$name.log" 2>&1 || rc=$?
  if [ "$rc" -ne "$code" ]; then
    cat "$work/$name.log" >&2
    fail "$name: exit code $rc, expected $code (command: $*)"
  fi
}
expect_output() {
  local name=$1 pattern=$2
  grep -Eq -- "$pattern" "$work/$name.log" || {
    cat "$work/$name.log" >&2
    fail "$name: output lacks /$pattern/"
  }
}

prefix=$work/install
unset STROMA_PLUGIN_PATH STROMA_DATA_PATH
example=$(cd "$here/../../examples/ForceFieldPlugin" && pwd)

if [ "$phase" = prepare ]; then
  rm -rf "$work"
  mkdir -p "$work"
  # 1. Install.
  expect install 0 "$cmake" --install "$build_dir" --prefix "$prefix"
  # 2. Build the external plugin and the example against the install only.
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  expect configure 0 "$cmake" -S "$here/external_plugin" -B "$work/external" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    "${launcher[@]}"
  expect build 0 "$cmake" --build "$work/external"
  expect configure_example 0 "$cmake" -S "$example" -B "$work/example" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}"
  expect build_example 0 "$cmake" --build "$work/example"
  echo "install_test: prepared (prefix $prefix)"
  exit 0
fi
[ "$phase" = check ] || fail "usage: install_test.sh prepare|check MAIN_BUILD_DIR WORK_DIR"
[ -d "$work/external" ] && [ -d "$work/example" ] ||
  fail "nothing prepared in $work: tests/tooling/prepare.sh $build_dir runs the install and" \
    "builds the out-of-tree plugins (scripts/test.sh runs it before ctest)"

# 1-2. What the install and the out-of-tree builds left.
[ -x "$prefix/bin/stroma" ] || fail "no bin/stroma in the install"
[ -f "$prefix/lib/cmake/Stroma/StromaConfig.cmake" ] || fail "no package config in the install"
ls "$prefix"/lib/stroma/plugins/*.stroma-plugin >/dev/null 2>&1 || fail "no installed plugin index"
# The plugin compiles with the framework's -march (Eigen's alignment is part of the plugin ABI).
march=$(grep -o -m1 -- '-march=[^ "]*' "$build_dir/compile_commands.json" || true)
if [ -n "$march" ] && ! grep -q -- "$march" "$work/external/compile_commands.json"; then
  fail "the external plugin does not compile with the framework's $march"
fi
plugins=$work/external/plugins
[ -f "$plugins/libExternalDemo.so" ] || fail "stroma_add_plugin put no libExternalDemo.so in $plugins"
[ -f "$plugins/ExternalDemo.stroma-plugin" ] || fail "no ExternalDemo.stroma-plugin index in $plugins"
grep -q '^component ExternalDemoComponent$' "$plugins/ExternalDemo.stroma-plugin" ||
  fail "the index does not list ExternalDemoComponent"

stroma=$prefix/bin/stroma
scene=$here/external_plugin/ExternalDemo.scn

# 3. The installed stroma lists the external component beside the built-in ones.
expect list 0 env STROMA_PLUGIN_PATH="$plugins" "$stroma" list
expect_output list '^ExternalDemo$'
expect_output list '^  ExternalDemoComponent: '
expect_output list '^  MechanicalObject'
expect list_plugin 0 env STROMA_PLUGIN_PATH="$plugins" "$stroma" list --plugin ExternalDemo
expect_output list_plugin '^  ExternalDemoComponent: '

# 4. ... and loads a scene that uses it, creating and initializing the component.
expect check 0 env STROMA_PLUGIN_PATH="$plugins" "$stroma" check "$scene" --verbose
expect_output check 'external component initialized with stiffness 250'
expect run 0 env STROMA_PLUGIN_PATH="$plugins" "$stroma" run "$scene" -n 3
expect doc_external 0 env STROMA_PLUGIN_PATH="$plugins" "$stroma" doc ExternalDemoComponent
expect_output doc_external 'plugin: ExternalDemo'
expect_output doc_external 'stiffness +\(.*unit N/m'

# 5. Without the plugin path the component is unknown: bad input (2), not a crash.
expect check_no_path 2 "$stroma" check "$scene"
expect_output check_no_path "ExternalDemoComponent"
# A value outside the Data's declared range is reported with the field.
sed 's/stiffness="250"/stiffness="-1"/' "$scene" >"$work/bad.scn"
expect check_bad_value 2 env STROMA_PLUGIN_PATH="$plugins" "$stroma" check "$work/bad.scn"
expect_output check_bad_value "stiffness"

# 6. The installed stroma uses the installed library and built-in plugins (the build tree is
# only a fallback of the search path). LD_DEBUG=files names every library the loader opens.
expect doc_builtin 0 env LD_DEBUG=files "$stroma" doc MechanicalObject
expect_output doc_builtin '^MechanicalObject'
expect_output doc_builtin "file=$prefix/lib/stroma/plugins/libStateContainer\.so"
expect_output doc_builtin "file=libStromaFramework\.so.*|file=$prefix/lib/libStromaFramework"
if grep -q "file=$build_dir/lib/" "$work/doc_builtin.log"; then
  fail "the installed stroma loaded a library from the build tree:" \
    "$(grep "file=$build_dir/lib/" "$work/doc_builtin.log" | head -1)"
fi
expect check_default 0 "$stroma" check "$prefix/share/stroma/scenes/organ/Organ.scn"

# 7. The example third-party force field (examples/ForceFieldPlugin), built the same way, gives
# the static equilibrium of its scene: u + 2 u^3 = F, u = 1 m for 3 N and u = 2 m for 18 N.
expect run_example 0 env STROMA_PLUGIN_PATH="$work/example/plugins" "$stroma" run \
  "$example/HardeningAnchor.scn" -n 1 --export-state "$work/example.state"
awk '
  $1 == "state" && $2 == "/root/Points/dofs" { row = 0; reading = 1; next }
  reading && row < 2 { x[row] = $1; y[row] = $2; z[row] = $3; ++row }
  function off(a, b) { d = a - b; return (d < 0 ? -d : d) > 1e-9 }
  END {
    if (row != 2) { print "no state of /root/Points/dofs"; exit 1 }
    if (off(x[0], 1) || off(y[0], 0) || off(z[0], 0) || off(x[1], 5) || off(y[1], 2) || off(z[1], 0)) {
      printf "equilibrium (%s %s %s) (%s %s %s), expected (1 0 0) (5 2 0)\n", x[0], y[0], z[0], x[1], y[1], z[1]
      exit 1
    }
  }' "$work/example.state" >"$work/example_check.log" 2>&1 ||
  fail "HardeningAnchor.scn: $(cat "$work/example_check.log")"
sed 's/hardening="2"/hardening="-2"/' "$example/HardeningAnchor.scn" >"$work/bad_example.scn"
expect check_bad_example 2 env STROMA_PLUGIN_PATH="$work/example/plugins" "$stroma" check \
  "$work/bad_example.scn"
expect_output check_bad_example "HardeningAnchorForceField.*hardening|hardening.*HardeningAnchorForceField"

echo "install_test: OK (prefix $prefix, plugins $plugins and $work/example/plugins)"
