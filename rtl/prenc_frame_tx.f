// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_frame_tx, relative to this folder (verilator -F, or -f from rtl/).
prenc_crc16.v
prenc_frame_tx.v
