// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_matrix_encoder (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_matrix_encoder.v
-F prenc_matrix_reader.f
../board/prenc_ssi.v
