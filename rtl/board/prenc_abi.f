// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_abi (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_step_tracker.v
prenc_abi.v
