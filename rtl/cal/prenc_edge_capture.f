// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_edge_capture (verilator -F <this file>), relative to this folder.
prenc_edge_capture.v
