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
// prenc_step_tracker follows the position sector by sector (one a clock at most), with
// the hysteresis of HYS ((3 - HYS) LSB of the 14-bit angle, as prenc_abi). U = V = W =
// 0, a pattern no Hall sensor makes, while the position is not valid and until the
// sector has caught up with it after reset: from then on the outputs are the shaft's.
//
// Latency: U, V and W are registers, 2 clocks after the position crossed a sector's edge.
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

  // floor(2^B / s) and 2^B mod s, at elaboration.
  function [31:0] turn_div(input [31:0] s);
    turn_div = (32'd1 << B) / s;
  endfunction
  function [31:0] turn_mod(input [31:0] s);
    turn_mod = (32'd1 << B) % s;
  endfunction
  localparam [31:0] FIXED = 6 * POLE_PAIRS;

  // The sectors of a turn, 6 P, and q, r for the tracker: POLE_PAIRS's, or UVWPP's (the
  // settings' choice, always computed, so that the block is combinational in every
  // simulator whichever is used).
  reg  [31:0] chosen_sectors;
  reg  [31:0] chosen_q;
  reg  [31:0] chosen_r;
  always @* begin
    case (settings2[2:0])
      3'd0:    begin chosen_sectors = 6;  chosen_q = turn_div(6);  chosen_r = turn_mod(6);  end
      3'd1:    begin chosen_sectors = 12; chosen_q = turn_div(12); chosen_r = turn_mod(12); end
      3'd2:    begin chosen_sectors = 18; chosen_q = turn_div(18); chosen_r = turn_mod(18); end
      3'd3:    begin chosen_sectors = 24; chosen_q = turn_div(24); chosen_r = turn_mod(24); end
      3'd4:    begin chosen_sectors = 30; chosen_q = turn_div(30); chosen_r = turn_mod(30); end
      3'd5:    begin chosen_sectors = 36; chosen_q = turn_div(36); chosen_r = turn_mod(36); end
      3'd6:    begin chosen_sectors = 42; chosen_q = turn_div(42); chosen_r = turn_mod(42); end
      default: begin   // 7, as 6
        chosen_sectors = 42; chosen_q = turn_div(42); chosen_r = turn_mod(42);
      end
    endcase
  end
  localparam [31:0] FIXED_Q = (POLE_PAIRS != 0) ? turn_div(FIXED) : 32'd0;
  localparam [31:0] FIXED_R = (POLE_PAIRS != 0) ? turn_mod(FIXED) : 32'd0;
  wire [31:0] sectors_32 = (POLE_PAIRS != 0) ? FIXED : chosen_sectors;
  wire [31:0] q_32       = (POLE_PAIRS != 0) ? FIXED_Q : chosen_q;
  wire [31:0] r_32       = (POLE_PAIRS != 0) ? FIXED_R : chosen_r;
  // The hysteresis: (3 - HYS) LSB of 14 bits, as prenc_abi's.
  wire [B-1:0]  hysteresis = {{(B - 2){1'b0}}, 2'd3 - settings2[4:3]} << (B - 14);
  wire          restart;   // the tracker starts again at sector 0 (after reset, a new P)
  wire [SB-1:0] count;
  wire          step;
  wire          up;
  wire          caught_up;

  prenc_step_tracker #(
    .B          (B),
    .STEPS_BITS (SB)
  ) u_sectors (
    .clk        (clk),
    .rst        (rst),
    .position   (position),
    .valid      (valid),
    .steps      (sectors_32[SB-1:0]),
    .q          (q_32[B-1:0]),
    .r          (r_32[SB-1:0]),
    .hysteresis (hysteresis),
    .min_gap    (16'd1),
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

  wire unused_ok = &{1'b0, count, settings2[7:5], sectors_32[31:SB], q_32[31:B], r_32[31:SB]};

endmodule

`resetall
