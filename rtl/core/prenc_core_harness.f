// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_core_harness (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
-F prenc_core.f
prenc_core_harness.v
