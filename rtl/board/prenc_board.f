// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_board (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
-F ../core/prenc_core.f
-F ../fine/prenc_fine.f
-F ../cal/prenc_edge_capture.f
-F prenc_host_link.f
-F ../health/prenc_health.f
prenc_ssi.v
prenc_turns.v
prenc_biss.v
prenc_as5047.v
prenc_step_tracker.v
prenc_abi.v
prenc_uvw.v
prenc_board.v
