// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_uart_rx, relative to this folder (verilator -F, or -f from rtl/).
prenc_uart_rx.v
