// SPDX-License-Identifier: Apache-2.0
// prenc_icestick: the reader on a Lattice iCEstick (iCE40 HX1K, 1,280 logic cells,
// 12 MHz oscillator).
//
//   12 MHz (pin 21) -> SB_PLL40_CORE -> 48 MHz system clock: BiSS-C's MA up to 9.6 MHz
//   power-on reset (prenc_power_on_reset): until the PLL locks, then 32 clocks (the
//   iCEstick has no button)
//   J2 (PMOD): 1 head1, 2 head2, 3 sync A, 4 sync B                      (inputs, 3.3 V)
//              7 SSI clock in, 8 SSI data out, 9 SSI Gray select (pulled up: Gray)
//   J1:        3 BiSS-C MA in (pulled up), 4 BiSS-C SLO out (through RS-422
//              transceivers to the drive: docs/biss-c.md)
//   LEDs:      D5 (green) pos_valid; D1..D4 (red) ACQUIRE, NORMAL, REDUCED, INCREMENTAL
//   UART:      the FTDI's second interface, RX pin 9, TX pin 8: with HOST_LINK = 0 (the
//              default, the HX1K's size) TX idles high and RX is unused
//
// What the HX1K holds (docs/guide/synthesis.md): the core, the multi-turn count, SSI and
// BiSS-C, with the core's HYPOTHESES = 0 (a missed quadrature state drops the position
// until the next lock; the goal table's price is in bench section 4b). No fine position
// or velocity (prenc_fine, FINE = 0): SSI and BiSS-C send pos_hyb, N + 2 bits. No
// warning before a failure (prenc_health, HEALTH = 0): nW only in a reduced mode.
//
// Parameters: N, TAPS, FILTER, ROM_FILE, BAUD as prenc_board; HOST_LINK and HYPOTHESES
// as prenc_board and prenc_core, with the iCEstick's defaults (0 and 0). The HX1K's 16
// block RAMs (64 kbit) hold the ROM up to N = 11 (1,263 LC at N = 11).

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_icestick #(
  parameter integer N          = 10,
  parameter [31:0]  TAPS       = 32'h0000_0204,
  parameter integer FILTER     = 2,
  parameter         ROM_FILE   = "prenc_rom_n10.hex",
  parameter integer BAUD       = 115200,
  parameter integer HOST_LINK  = 0,
  parameter integer HYPOTHESES = 0
) (
  input  wire CLK,
  input  wire RX,
  output wire TX,
  input  wire PMOD1,
  input  wire PMOD2,
  input  wire PMOD3,
  input  wire PMOD4,
  input  wire PMOD7,
  output wire PMOD8,
  input  wire PMOD9,
  input  wire J1_3,
  output wire J1_4,
  output wire LED1,
  output wire LED2,
  output wire LED3,
  output wire LED4,
  output wire LED5
);

  localparam integer CLK_HZ = 48000000;

  wire clk;
  wire locked;

  // 12 MHz x 64 / 2^4 = 48 MHz (yowasp-icepll -i 12 -o 48): VCO 768 MHz. Pin 21 is not
  // a PLL pad, so the PLL takes its reference from the fabric (SB_PLL40_CORE).
  SB_PLL40_CORE #(
    .FEEDBACK_PATH ("SIMPLE"),
    .DIVR          (4'b0000),
    .DIVF          (7'b0111111),
    .DIVQ          (3'b100),
    .FILTER_RANGE  (3'b001)
  ) u_pll (
    .REFERENCECLK (CLK),
    .PLLOUTGLOBAL (clk),
    .LOCK         (locked),
    .RESETB       (1'b1),
    .BYPASS       (1'b0)
  );

  // Power-on reset, synchronous to the PLL clock.
  wire rst;

  prenc_power_on_reset #(
    .HOLD (32)
  ) u_reset (
    .clk    (clk),
    .locked (locked),
    .button (1'b0),
    .rst    (rst)
  );

  wire       pos_valid;
  wire [2:0] mode;
  wire       led_valid;
  wire       led_normal;
  wire       led_reduced;
  wire       led_incremental;
  wire       led_acquire;
  wire       spi_miso;       // no SPI, ABI, UVW on the HX1K: it has no room
  wire       spi_miso_oe;
  wire       abi_a, abi_b, abi_i;
  wire       uvw_u, uvw_v, uvw_w;

  prenc_board #(
    .N          (N),
    .TAPS       (TAPS),
    .FILTER     (FILTER),
    .ROM_FILE   (ROM_FILE),
    .CLK_HZ     (CLK_HZ),
    .BAUD       (BAUD),
    .HOST_LINK  (HOST_LINK),
    .HYPOTHESES (HYPOTHESES),
    .FINE       (0),
    .HEALTH     (0),
    .SPI        (0),
    .ABI        (0),
    .UVW        (0)
  ) u_board (
    .clk             (clk),
    .rst             (rst),
    .head1           (PMOD1),
    .head2           (PMOD2),
    .sync_a          (PMOD3),
    .sync_b          (PMOD4),
    .uart_rx         (RX),
    .uart_tx         (TX),
    .ssi_clk         (PMOD7),
    .ssi_data        (PMOD8),
    .ssi_gray        (PMOD9),
    .biss_ma         (J1_3),
    .biss_slo        (J1_4),
    .spi_csn         (1'b1),
    .spi_sclk        (1'b0),
    .spi_mosi        (1'b1),
    .spi_miso        (spi_miso),
    .spi_miso_oe     (spi_miso_oe),
    .abi_a           (abi_a),
    .abi_b           (abi_b),
    .abi_i           (abi_i),
    .uvw_u           (uvw_u),
    .uvw_v           (uvw_v),
    .uvw_w           (uvw_w),
    .led_valid       (led_valid),
    .led_normal      (led_normal),
    .led_reduced     (led_reduced),
    .led_incremental (led_incremental),
    .led_acquire     (led_acquire),
    .pos_valid       (pos_valid),
    .mode            (mode)
  );

  assign LED1 = led_acquire;
  assign LED2 = led_normal;
  assign LED3 = led_reduced;
  assign LED4 = led_incremental;
  assign LED5 = led_valid;

  wire unused_ok = &{1'b0, pos_valid, mode, spi_miso, spi_miso_oe, abi_a, abi_b, abi_i,
                     uvw_u, uvw_v, uvw_w};

endmodule

`resetall
