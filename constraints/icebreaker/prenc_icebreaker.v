// SPDX-License-Identifier: Apache-2.0
// prenc_icebreaker: the reader on an iCEBreaker (iCE40 UP5K, 12 MHz oscillator).
//
//   12 MHz (pin 35) -> SB_PLL40_PAD -> 30 MHz system clock: 3 Mbaud is 10 clocks per bit,
//   1 Mbaud 30, 115200 baud 260 (0.2 % fast). The UP5K closes this top at about 30 to
//   32 MHz (make synth; docs/guide/synthesis.md has each build's figure).
//   power-on reset (prenc_power_on_reset): until the PLL locks, then 32 clocks; BTN_N too
//   PMOD1A: P1A1 head1, P1A2 head2, P1A3 sync A, P1A4 sync B      (inputs, 3.3 V)
//           P1A7 SSI clock in, P1A8 SSI data out, P1A9 SSI Gray select (pulled up: Gray)
//   PMOD1B: P1B1 BiSS-C MA in (pulled up), P1B2 BiSS-C SLO out (through RS-422
//           transceivers to the drive: docs/biss-c.md)
//           P1B7 SPI CSn in (pulled up), P1B8 SCLK in, P1B9 MOSI in (pulled up: a drive
//           that has no MOSI reads ANGLECOM), P1B10 MISO out (high impedance while CSn
//           is high: docs/interfaces/as5047.md)
//           P1B3 A, P1B4 B out, P1A10 I out (ABI: docs/interfaces/abi-uvw.md)
//   UART:   RX pin 6, TX pin 9, to the on-board FTDI (second interface)
//   LEDs:   LEDG_N pos_valid, LEDR_N not valid; PMOD2 snap-off LED1..LED5:
//           ACQUIRE, NORMAL, REDUCED, INCREMENTAL, pos_valid
//   UVW = 1: U, V, W on LED1, LED2, LED3 (PMOD2 pins 1 to 3 without the snap-off).
//   With CAL = 1 and no CAL_FILE (the build that `prenc calibrate` runs on: an empty
//   table, and the edges' capture) neither SPI nor ABI nor the warning before a failure
//   (prenc_health: nW only in a reduced mode): the capture takes their room. With the
//   disc's table built in (CAL_FILE) there is no capture, and SPI, ABI and the warning
//   are built.
//
// Parameters: N, TAPS, FILTER, ROM_FILE, BAUD as prenc_board. The UP5K's 30 block
// RAMs (120 kbit) hold the ROM up to N = 12. FINE (1): the fine position and velocity;
// 0: not built (SSI and BiSS-C send pos_hyb). CAL (1, with FINE = 1): the calibration
// table (docs/calibration.md), written over the host link (`prenc calibrate`) or built
// in from CAL_FILE (then without the edges' capture). FINE_BITS, BISS_MT_BITS,
// BISS_ST_BITS, BISS_ERROR_HIGH, SPI_ZERO, SPI_SETTINGS1, SPI_SETTINGS2, ABI_STEPS,
// ABI_EDGE_NS, SSI_WARNING, WARN_SLOTS, WARN_BURST, UVW_POLE_PAIRS, EDGE_TOLERANCE:
// prenc_board's (make synth PARAMS="NAME=VALUE ..."). UVW (0): 1 builds U, V, W (not
// with CAL = 1). SPI, ABI (1): 0 leaves that drive's output out (its pins idle: MISO
// high impedance, A, B, I low), for room and timing margin on a full UP5K.

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_icebreaker #(
  parameter integer N        = 10,
  parameter [31:0]  TAPS     = 32'h0000_0204,
  parameter integer FILTER   = 2,
  parameter         ROM_FILE = "prenc_rom_n10.hex",
  parameter integer BAUD     = 115200,
  parameter integer FINE     = 1,
  parameter integer CAL      = 0,
  parameter         CAL_FILE = "",
  parameter integer EDGE_TOLERANCE  = 0,
  parameter integer FINE_BITS       = 0,
  parameter integer BISS_MT_BITS    = 12,
  parameter integer BISS_ST_BITS    = 0,
  parameter integer BISS_ERROR_HIGH = 0,
  parameter integer SPI_ZERO        = 0,
  parameter integer SPI_SETTINGS1   = 1,
  parameter integer SPI_SETTINGS2   = 0,
  parameter integer ABI_STEPS       = 0,
  parameter integer ABI_EDGE_NS     = 250,
  parameter integer SSI_WARNING     = 0,
  parameter integer WARN_SLOTS      = 128,
  parameter integer WARN_BURST      = 8,
  parameter integer UVW             = 0,
  parameter integer UVW_POLE_PAIRS  = 0,
  parameter integer SPI             = 1,
  parameter integer ABI             = 1
) (
  input  wire CLK,
  input  wire BTN_N,
  input  wire RX,
  output wire TX,
  input  wire P1A1,
  input  wire P1A2,
  input  wire P1A3,
  input  wire P1A4,
  input  wire P1A7,
  output wire P1A8,
  input  wire P1A9,
  input  wire P1B1,
  output wire P1B2,
  input  wire P1B7,
  input  wire P1B8,
  input  wire P1B9,
  output wire P1B10,
  output wire P1B3,
  output wire P1B4,
  output wire P1A10,
  output wire LEDR_N,
  output wire LEDG_N,
  output wire LED1,
  output wire LED2,
  output wire LED3,
  output wire LED4,
  output wire LED5
);

  localparam integer CLK_HZ = 30000000;
  // Beside the calibration table the UP5K has room either for the edges' capture (the
  // build to calibrate on: CAL = 1, no CAL_FILE) or for the drives' SPI and ABI and the
  // warning (the disc's table built in).
  localparam integer CAPTURE = (CAL == 1 && CAL_FILE == "") ? 1 : 0;
  localparam integer DRIVES  = 1 - CAPTURE;
  localparam integer HEALTH  = 1 - CAPTURE;
  localparam integer SPI_ON  = (DRIVES == 1 && SPI == 1) ? 1 : 0;
  localparam integer ABI_ON  = (DRIVES == 1 && ABI == 1) ? 1 : 0;

  generate
    if (SPI != 0 && SPI != 1) begin : g_bad_spi
      initial $display("ERROR: %m: parameter SPI = %0d must be 0 or 1", SPI);
      prenc_icebreaker_parameter_SPI_must_be_0_or_1 u_stop ();
    end
    if (ABI != 0 && ABI != 1) begin : g_bad_abi
      initial $display("ERROR: %m: parameter ABI = %0d must be 0 or 1", ABI);
      prenc_icebreaker_parameter_ABI_must_be_0_or_1 u_stop ();
    end
    if (UVW != 0 && UVW != 1) begin : g_bad_uvw
      initial $display("ERROR: %m: parameter UVW = %0d must be 0 or 1", UVW);
      prenc_icebreaker_parameter_UVW_must_be_0_or_1 u_stop ();
    end
    if (UVW == 1 && CAL == 1) begin : g_uvw_and_cal
      initial $display("ERROR: %m: UVW = 1 and CAL = 1: the UP5K has no room for both");
      prenc_icebreaker_UVW_and_CAL_do_not_fit_together u_stop ();
    end
  endgenerate

  wire clk;
  wire locked;

  // 12 MHz x 80 / 2^5 = 30 MHz (yowasp-icepll -i 12 -o 30): VCO 960 MHz.
  SB_PLL40_PAD #(
    .FEEDBACK_PATH ("SIMPLE"),
    .DIVR          (4'b0000),
    .DIVF          (7'b1001111),
    .DIVQ          (3'b101),
    .FILTER_RANGE  (3'b001)
  ) u_pll (
    .PACKAGEPIN   (CLK),
    .PLLOUTGLOBAL (clk),
    .LOCK         (locked),
    .RESETB       (1'b1),
    .BYPASS       (1'b0)
  );

  // Power-on and button reset, synchronous to the PLL clock.
  wire rst;

  prenc_power_on_reset #(
    .HOLD (32)
  ) u_reset (
    .clk    (clk),
    .locked (locked),
    .button (~BTN_N),
    .rst    (rst)
  );

  wire       pos_valid;
  wire [2:0] mode;
  wire       led_valid;
  wire       led_normal;
  wire       led_reduced;
  wire       led_incremental;
  wire       led_acquire;
  wire       spi_miso;
  wire       spi_miso_oe;
  wire       uvw_u;          // UVW = 0: not built, 0
  wire       uvw_v;
  wire       uvw_w;

  prenc_board #(
    .N        (N),
    .TAPS     (TAPS),
    .FILTER   (FILTER),
    .ROM_FILE (ROM_FILE),
    .CLK_HZ   (CLK_HZ),
    .BAUD     (BAUD),
    .FINE         (FINE),
    .EDGE_CAPTURE (CAPTURE),
    .CAL          (CAL),
    .CAL_FILE     (CAL_FILE),
    .EDGE_TOLERANCE  (EDGE_TOLERANCE),
    .FINE_BITS       (FINE_BITS),
    .BISS_MT_BITS    (BISS_MT_BITS),
    .BISS_ST_BITS    (BISS_ST_BITS),
    .BISS_ERROR_HIGH (BISS_ERROR_HIGH),
    .SPI_ZERO        (SPI_ZERO),
    .SPI_SETTINGS1   (SPI_SETTINGS1),
    .SPI_SETTINGS2   (SPI_SETTINGS2),
    .ABI_STEPS       (ABI_STEPS),
    .ABI_EDGE_NS     (ABI_EDGE_NS),
    .SSI_WARNING     (SSI_WARNING),
    .WARN_SLOTS      (WARN_SLOTS),
    .WARN_BURST      (WARN_BURST),
    .SPI             (SPI_ON),
    .ABI             (ABI_ON),
    .HEALTH          (HEALTH),
    .UVW             (UVW),
    .UVW_POLE_PAIRS  (UVW_POLE_PAIRS)
  ) u_board (
    .clk             (clk),
    .rst             (rst),
    .head1           (P1A1),
    .head2           (P1A2),
    .sync_a          (P1A3),
    .sync_b          (P1A4),
    .uart_rx         (RX),
    .uart_tx         (TX),
    .ssi_clk         (P1A7),
    .ssi_data        (P1A8),
    .ssi_gray        (P1A9),
    .biss_ma         (P1B1),
    .biss_slo        (P1B2),
    .spi_csn         (P1B7),
    .spi_sclk        (P1B8),
    .spi_mosi        (P1B9),
    .spi_miso        (spi_miso),
    .spi_miso_oe     (spi_miso_oe),
    .abi_a           (P1B3),
    .abi_b           (P1B4),
    .abi_i           (P1A10),
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

  // MISO: a tristate output, driven while the SPI's CSn is low.
  SB_IO #(
    .PIN_TYPE (6'b1010_01)
  ) u_miso (
    .PACKAGE_PIN   (P1B10),
    .OUTPUT_ENABLE (spi_miso_oe),
    .D_OUT_0       (spi_miso)
  );

  assign LEDG_N = ~led_valid;
  assign LEDR_N = led_valid;
  // UVW = 1: U, V, W take the snap-off's first three LEDs' pins (PMOD2 1, 2, 3 without
  // the snap-off board).
  assign LED1   = (UVW == 1) ? uvw_u : led_acquire;
  assign LED2   = (UVW == 1) ? uvw_v : led_normal;
  assign LED3   = (UVW == 1) ? uvw_w : led_reduced;
  assign LED4   = led_incremental;
  assign LED5   = pos_valid;

  wire unused_ok = &{1'b0, mode, uvw_u, uvw_v, uvw_w, led_acquire, led_normal, led_reduced};

endmodule

`resetall
