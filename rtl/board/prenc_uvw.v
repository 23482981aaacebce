// SPDX-License-Identifier: Apache-2.0
// prenc_uvw: U, V, W commutation signals, as the AS5047P's UVW outputs (Hall sensors'
// pattern; docs/interfaces/abi-uvw.md).
//
// P pole pairs (SETTINGS2 bits 2:0, UVWPP: P = UVWPP + 1, 1 to 7, UVWPP 7 also 7;
// POLE_PAIRS, when not 0, instead: 1 to 32) cut the turn into 6 P sectors of 60 electrical degrees,
// counted from the zero (ZPOS: an electrical zero stored there needs no alignment
// run). In sector s (0..5 of each electrical turn):
//
//   s   0 1 2 3 4 5          U high from 0 to 180 electrical degrees,
//   U   1 1 1 0 0 0          V from 120 to 300, W from 240 to 60:
//   V   0 0 1 1 1 0          each 120 degrees after the one before
//   W   1 0 0 0 1 1
//
// prenc_step_tracker follows the position sector by sector (one every 3 clocks at most), with
// the hysteresis of HYS ((3 - HYS) LSB of the 14-bit angle, as prenc_abi). U = V = W =
// 0, a pattern no Hall sensor makes, while the position is not valid and until the
// sector has caught up with it after reset: from then on the outputs are the shaft's.
//
// Latency: U, V and W are registers, 5 clocks after the position crossed a sector's edge.
//
// Parameters
//   B            position bits, 14..30 (the turn is 2^B positions)
//   POLE_PAIRS   0: from UVWPP (1 to 7); else 1..32
//
// Ports
//   clk, rst            one clock; synchronous active-high reset
//   position, valid     the position with the zero and DIR applied (2^-B turn)
//   settings2           prenc_as5047's register (UVWPP, HYS)
//   u, v, w             the outputs

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_uvw #(
  parameter integer B          = 14,
  parameter integer POLE_PAIRS = 0
) (
  input  wire         clk,
  input  wire         rst,
  input  wire [B-1:0] position,
  input  wire         valid,
  input  wire [7:0]   settings2,
  output wire         u,
  output wire         v,
  output wire         w
);

  generate
    if (B < 14 || B > 30) begin : g_bad_b
      initial $display("ERROR: %m: parameter B = %0d is out of range 14..30", B);
      prenc_uvw_parameter_B_out_of_range_14_to_30 u_stop ();
    end
    if (POLE_PAIRS < 0 || POLE_PAIRS > 32) begin : g_bad_pole_pairs
      initial $display("ERROR: %m: parameter POLE_PAIRS = %0d is out of range 0..32", POLE_PAIRS);
      prenc_uvw_parameter_POLE_PAIRS_out_of_range_0_to_32 u_stop ();
    end
  endgenerate

  localparam integer SB = 8;   // 6 P <= 192 sectors

  localparam [31:0] FIXED = 6 * POLE_PAIRS;

  // The sectors of a turn, 6 P: POLE_PAIRS's, or UVWPP's.
  reg  [31:0] chosen_sectors;
  always @* begin
    case (settings2[2:0])
      3'd0:    chosen_sectors = 6;
      3'd1:    chosen_sectors = 12;
      3'd2:    chosen_sectors = 18;
      3'd3:    chosen_sectors = 24;
      3'd4:    chosen_sectors = 30;
      3'd5:    chosen_sectors = 36;
      default: chosen_sectors = 42;   // 6 and 7: 7 pole pairs
    endcase
  end
  wire [31:0] sectors_32 = (POLE_PAIRS != 0) ? FIXED : chosen_sectors;
  // The hysteresis: (3 - HYS) LSB of 14 bits, in 2^-16 turn, as prenc_abi's.
  wire [15:0]   hysteresis = {12'd0, 2'd3 - settings2[4:3], 2'b00};
  wire          restart;   // the tracker starts again at sector 0 (after reset, a new P)
  wire [SB-1:0] count;
  wire          step;
  wire          up;
  wire          caught_up;

  prenc_step_tracker #(
    .B          (B),
    .STEPS_BITS (SB),
    .MIN_GAP    (1)
  ) u_sectors (
    .clk        (clk),
    .rst        (rst),
    .position   (position),
    .valid      (valid),
    .steps      (sectors_32[SB-1:0]),
    .hysteresis (hysteresis),
    .restart    (restart),
    .count      (count),
    .step       (step),
    .up         (up),
    .caught_up  (caught_up)
  );

  // The sector within the electrical turn: the count modulo 6, kept beside it.
  reg [2:0] sector;
  reg       placed;
  reg [2:0] uvw;
  always @(posedge clk) begin
    if (step) begin
      if (up) begin
        sector <= (sector == 3'd5) ? 3'd0 : sector + 3'd1;
      end else begin
        sector <= (sector == 3'd0) ? 3'd5 : sector - 3'd1;
      end
    end
    if (caught_up) begin
      placed <= 1'b1;
    end
    if (!valid) begin
      uvw <= 3'b000;
    end else if (placed) begin
      case (sector)
        3'd0:    uvw <= 3'b101;
        3'd1:    uvw <= 3'b100;
        3'd2:    uvw <= 3'b110;
        3'd3:    uvw <= 3'b010;
        3'd4:    uvw <= 3'b011;
        default: uvw <= 3'b001;
      endcase
    end
    if (rst || restart) begin
      sector <= 3'd0;
      placed <= 1'b0;
      uvw    <= 3'b000;
    end
  end

  assign u = uvw[2];
  assign v = uvw[1];
  assign w = uvw[0];

  wire unused_ok = &{1'b0, count, settings2[7:5], sectors_32[31:SB]};

endmodule

`resetall
