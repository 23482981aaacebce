// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_wb (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
-F ../core/prenc_core.f
-F ../fine/prenc_fine.f
-F ../health/prenc_health.f
prenc_wb.v
