// SPDX-License-Identifier: Apache-2.0
// prenc_ulx3s: the reader on a ULX3S (ECP5 LFE5U-85F, 25 MHz oscillator).
//
//   25 MHz (G2) -> EHXPLLL -> 50 MHz system clock (x2; an ECP5 PLL cannot make
//   48 MHz from 25 MHz with a legal PFD). Baud rates: 115200 (434 clocks per bit),
//   1 and 2 Mbaud exact; 3 Mbaud is 17 clocks per bit, 2 % slow (2.94 Mbaud).
//   power-on reset (prenc_power_on_reset): until the PLL locks, then 32 clocks; FIRE1 too
//   J1 header: GP0 head1, GN0 head2, GP1 sync A, GN1 sync B            (inputs, 3.3 V)
//              (the top's ports are inputs and outputs only, GN2 and GN4 as their own
//              ports: an `inout` bus with bits left undriven became outputs driving 0
//              in the netlist, which tb/board/netlist found on GN0 and GN1)
//              GP2 SSI clock in, GN2 SSI data out, GP3 SSI Gray select (pulled up: Gray)
//              GP4 BiSS-C MA in (pulled up), GN4 BiSS-C SLO out (through RS-422
//              transceivers to the drive: docs/biss-c.md)
//              GP5 SPI CSn in (pulled up), GN5 SCLK in (pulled down), GP6 MOSI in
//              (pulled up: a drive that has no MOSI reads ANGLECOM), GN6 MISO out (high
//              impedance while CSn is high: docs/interfaces/as5047.md)
//              GP7 A, GN7 B, GP8 I out; GN8 U, GP9 V, GN9 W out
//              (docs/interfaces/abi-uvw.md)
//   UART:      ftdi_txd (M1) in, ftdi_rxd (L4) out, the on-board FT231X
//   LEDs:      led[0] pos_valid, led[1] ACQUIRE, led[2] NORMAL, led[3] REDUCED,
//              led[4] INCREMENTAL
//
// Parameters: N, TAPS, FILTER, ROM_FILE, BAUD, CAL, CAL_FILE as prenc_board; FINE_BITS,
// BISS_MT_BITS, BISS_ST_BITS, BISS_ERROR_HIGH, SPI_ZERO, SPI_SETTINGS1, SPI_SETTINGS2,
// ABI_STEPS, ABI_EDGE_NS, UVW_POLE_PAIRS, SSI_WARNING, WARN_SLOTS, WARN_BURST,
// EDGE_TOLERANCE too (make synth PARAMS="NAME=VALUE ...").

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_ulx3s #(
  parameter integer N        = 10,
  parameter [31:0]  TAPS     = 32'h0000_0204,
  parameter integer FILTER   = 2,
  parameter         ROM_FILE = "prenc_rom_n10.hex",
  parameter integer BAUD     = 115200,
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
  parameter integer UVW_POLE_PAIRS  = 0,
  parameter integer SSI_WARNING     = 0,
  parameter integer WARN_SLOTS      = 128,
  parameter integer WARN_BURST      = 8
) (
  input  wire       clk_25mhz,
  input  wire [1:1] btn,
  input  wire       ftdi_txd,
  output wire       ftdi_rxd,
  input  wire [6:0] gp,
  input  wire [1:0] gn,
  output wire       gn2,
  output wire       gn4,
  input  wire       gn5,
  output wire       gn6,
  output wire       gp7,
  output wire       gn7,
  output wire       gp8,
  output wire       gn8,
  output wire       gp9,
  output wire       gn9,
  output wire [7:0] led,
  output wire       wifi_gpio0
);

  localparam integer CLK_HZ = 50000000;

  wire clk;
  wire locked;

  // 25 MHz x 2 = 50 MHz (yowasp-ecppll -i 25 -o 50): VCO 600 MHz.
  (* FREQUENCY_PIN_CLKI="25" *)
  (* FREQUENCY_PIN_CLKOP="50" *)
  (* ICP_CURRENT="12" *) (* LPF_RESISTOR="8" *) (* MFG_ENABLE_FILTEROPAMP="1" *) (* MFG_GMCREF_SEL="2" *)
  EHXPLLL #(
    .PLLRST_ENA      ("DISABLED"),
    .INTFB_WAKE      ("DISABLED"),
    .STDBY_ENABLE    ("DISABLED"),
    .DPHASE_SOURCE   ("DISABLED"),
    .OUTDIVIDER_MUXA ("DIVA"),
    .OUTDIVIDER_MUXB ("DIVB"),
    .OUTDIVIDER_MUXC ("DIVC"),
    .OUTDIVIDER_MUXD ("DIVD"),
    .CLKI_DIV        (1),
    .CLKOP_ENABLE    ("ENABLED"),
    .CLKOP_DIV       (12),
    .CLKOP_CPHASE    (5),
    .CLKOP_FPHASE    (0),
    .FEEDBK_PATH     ("CLKOP"),
    .CLKFB_DIV       (2)
  ) u_pll (
    .RST          (1'b0),
    .STDBY        (1'b0),
    .CLKI         (clk_25mhz),
    .CLKOP        (clk),
    .CLKFB        (clk),
    .CLKINTFB     (),
    .PHASESEL0    (1'b0),
    .PHASESEL1    (1'b0),
    .PHASEDIR     (1'b1),
    .PHASESTEP    (1'b1),
    .PHASELOADREG (1'b1),
    .PLLWAKESYNC  (1'b0),
    .ENCLKOP      (1'b0),
    .LOCK         (locked)
  );

  // Power-on and button reset, synchronous to the PLL clock.
  wire rst;

  prenc_power_on_reset #(
    .HOLD (32)
  ) u_reset (
    .clk    (clk),
    .locked (locked),
    .button (btn[1]),
    .rst    (rst)
  );

  wire       pos_valid;
  wire [2:0] mode;
  wire       ssi_data;
  wire       biss_slo;
  wire       spi_miso;
  wire       spi_miso_oe;

  prenc_board #(
    .N        (N),
    .TAPS     (TAPS),
    .FILTER   (FILTER),
    .ROM_FILE (ROM_FILE),
    .CLK_HZ   (CLK_HZ),
    .BAUD     (BAUD),
    .CAL      (CAL),
    .CAL_FILE (CAL_FILE),
    .EDGE_TOLERANCE (EDGE_TOLERANCE),
    .FINE_BITS       (FINE_BITS),
    .BISS_MT_BITS    (BISS_MT_BITS),
    .BISS_ST_BITS    (BISS_ST_BITS),
    .BISS_ERROR_HIGH (BISS_ERROR_HIGH),
    .SPI_ZERO        (SPI_ZERO),
    .SPI_SETTINGS1   (SPI_SETTINGS1),
    .SPI_SETTINGS2   (SPI_SETTINGS2),
    .ABI_STEPS       (ABI_STEPS),
    .ABI_EDGE_NS     (ABI_EDGE_NS),
    .UVW_POLE_PAIRS  (UVW_POLE_PAIRS),
    .SSI_WARNING     (SSI_WARNING),
    .WARN_SLOTS      (WARN_SLOTS),
    .WARN_BURST      (WARN_BURST)
  ) u_board (
    .clk             (clk),
    .rst             (rst),
    .head1           (gp[0]),
    .head2           (gn[0]),
    .sync_a          (gp[1]),
    .sync_b          (gn[1]),
    .uart_rx         (ftdi_txd),
    .uart_tx         (ftdi_rxd),
    .ssi_clk         (gp[2]),
    .ssi_data        (ssi_data),
    .ssi_gray        (gp[3]),
    .biss_ma         (gp[4]),
    .biss_slo        (biss_slo),
    .spi_csn         (gp[5]),
    .spi_sclk        (gn5),
    .spi_mosi        (gp[6]),
    .spi_miso        (spi_miso),
    .spi_miso_oe     (spi_miso_oe),
    .abi_a           (gp7),
    .abi_b           (gn7),
    .abi_i           (gp8),
    .uvw_u           (gn8),
    .uvw_v           (gp9),
    .uvw_w           (gn9),
    .led_valid       (led[0]),
    .led_acquire     (led[1]),
    .led_normal      (led[2]),
    .led_reduced     (led[3]),
    .led_incremental (led[4]),
    .pos_valid       (pos_valid),
    .mode            (mode)
  );

  // MISO: a tristate output (OBZ: T = 1 is high impedance), driven while CSn is low.
  OBZ u_miso (
    .I (spi_miso),
    .T (~spi_miso_oe),
    .O (gn6)
  );

  assign gn2        = ssi_data;
  assign gn4        = biss_slo;
  assign led[7:5]   = 3'b000;
  assign wifi_gpio0 = 1'b1;  // keep the ESP32 from resetting the FPGA

  wire unused_ok = &{1'b0, pos_valid, mode};

endmodule

`resetall
