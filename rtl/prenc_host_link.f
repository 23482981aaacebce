// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_host_link, relative to this folder (verilator -F, or -f from rtl/).
prenc_crc16.v
prenc_uart_rx.v
prenc_uart_tx.v
prenc_frame_rx.v
prenc_frame_tx.v
prenc_host_link.v
