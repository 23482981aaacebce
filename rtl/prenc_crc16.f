// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_crc16, relative to this folder (verilator -F, or -f from rtl/).
prenc_crc16.v
