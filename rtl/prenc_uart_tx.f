// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_uart_tx, relative to this folder (verilator -F, or -f from rtl/).
prenc_uart_tx.v
