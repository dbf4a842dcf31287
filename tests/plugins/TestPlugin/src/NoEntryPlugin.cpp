// SPDX-License-Identifier: MIT
// A shared library that is not a Stroma plugin: it has no stroma_plugin_entry.
extern "C" __attribute__((visibility("default"))) int stroma_test_not_a_plugin() { return 42; }
