// SPDX-License-Identifier: Apache-2.0
// prenc_abi: A/B quadrature with an index, as the AS5047P's ABI outputs
// (docs/interfaces/abi-uvw.md).
//
// The turn is cut into S steps (quadrature states): S = STEPS if it is not 0, else the
// AS5047P's ABIRES (SETTINGS2 bits 7:5) and ABIBIN (SETTINGS1 bit 5): ABIBIN 0, ABIRES 0
// to 7: 4000, 2000, 1600, 1200, 800, 400, 200, 100 steps; ABIBIN 1: 4096, 2048, 1024
// (ABIRES 2 to 7: 1024). prenc_step_tracker follows the position's top 16 bits one step
// at a time, at most one step every MIN_GAP clocks (3 at least); A and B are its step
// count's quadrature (A leads B as the count goes up: 00, 10, 11, 01), the index I is
// high on step 0 (a quarter of A's period, A = B = 0) once the count has first caught up
// with the position.
// - Hysteresis: (3 - HYS) LSB of the 14-bit angle (SETTINGS2 bits 4:3; HYS 3: none), as
//   the SimpleFOC drivers' setHysteresis writes it.
// - After reset the count is 0 at the zero (A = B = 0); when the position becomes valid
//   the outputs step to it the shorter way round, so a counter that started with the
//   board holds the absolute step; the index shows from then on. While the position is
//   not valid, A, B and I hold. A new S starts again from step 0 at the zero.
// - A disc faster than S / max(MIN_GAP, 3) steps per clock is followed at that rate,
//   every step on A and B, and caught up when it slows.
//
// Latency: A, B and I are registers, 4 clocks after the position crossed a step's edge
// (at most one step every MIN_GAP clocks); a new S restarts them 2 clocks after it is
// written, and a new HYS counts from the next step.
//
// Parameters
//   B         position bits, 14..30 (the turn is 2^B positions)
//   STEPS     steps per turn, a multiple of 4 from 4 to 2^15; 0: from ABIRES and ABIBIN
//   MIN_GAP   clocks from a step of A or B to the next, 1..65535 (1 and 2 pace as 3)
//
// Ports
//   clk, rst            one clock; synchronous active-high reset
//   position, valid     the position with the zero and DIR applied (2^-B turn)
//   settings1, settings2   prenc_as5047's registers (ABIBIN; ABIRES, HYS)
//   a, b, i             the outputs

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_abi #(
  parameter integer B       = 14,
  parameter integer STEPS   = 0,
  parameter integer MIN_GAP = 8
) (
  input  wire         clk,
  input  wire         rst,
  input  wire [B-1:0] position,
  input  wire         valid,
  input  wire [7:0]   settings1,
  input  wire [7:0]   settings2,
  output wire         a,
  output wire         b,
  output wire         i
);

  generate
    if (B < 14 || B > 30) begin : g_bad_b
      initial $display("ERROR: %m: parameter B = %0d is out of range 14..30", B);
      prenc_abi_parameter_B_out_of_range_14_to_30 u_stop ();
    end
    if (STEPS != 0 && (STEPS < 4 || STEPS % 4 != 0 || STEPS > (1 << 15)))
    begin : g_bad_steps
      initial $display("ERROR: %m: parameter STEPS = %0d must be 0 or a multiple of 4, 4..2^15",
                       STEPS);
      prenc_abi_parameter_STEPS_must_be_0_or_a_multiple_of_4_up_to_2_to_the_15 u_stop ();
    end
    if (MIN_GAP < 1 || MIN_GAP > 65535) begin : g_bad_min_gap
      initial $display("ERROR: %m: parameter MIN_GAP = %0d is out of range 1..65535", MIN_GAP);
      prenc_abi_parameter_MIN_GAP_out_of_range_1_to_65535 u_stop ();
    end
  endgenerate

  // Bits of S and of the count: 13 (4096) or STEPS's.
  function integer bits_of(input integer value);
    integer v;
    begin
      bits_of = 0;
      for (v = value; v > 0; v = v / 2) bits_of = bits_of + 1;
    end
  endfunction
  localparam integer SB = (STEPS > 4096) ? bits_of(STEPS) : 13;

  localparam [31:0] STEPS_32 = STEPS;

  // S for the settings.
  reg [31:0] steps_32;
  always @* begin
    if (STEPS != 0) begin
      steps_32 = STEPS_32;
    end else if (settings1[5]) begin
      case (settings2[7:5])
        3'd0:    steps_32 = 4096;
        3'd1:    steps_32 = 2048;
        default: steps_32 = 1024;
      endcase
    end else begin
      case (settings2[7:5])
        3'd0:    steps_32 = 4000;
        3'd1:    steps_32 = 2000;
        3'd2:    steps_32 = 1600;
        3'd3:    steps_32 = 1200;
        3'd4:    steps_32 = 800;
        3'd5:    steps_32 = 400;
        3'd6:    steps_32 = 200;
        default: steps_32 = 100;
      endcase
    end
  end

  // The hysteresis: (3 - HYS) LSB of 14 bits, in 2^-16 turn.
  wire [15:0]   hysteresis = {12'd0, 2'd3 - settings2[4:3], 2'b00};
  wire          restart;   // the tracker starts again at step 0 (after reset, a new S)
  wire [SB-1:0] count;
  wire         step;
  wire         up;
  wire         caught_up;

  prenc_step_tracker #(
    .B          (B),
    .STEPS_BITS (SB),
    .MIN_GAP    (MIN_GAP)
  ) u_steps (
    .clk        (clk),
    .rst        (rst),
    .position   (position),
    .valid      (valid),
    .steps      (steps_32[SB-1:0]),
    .hysteresis (hysteresis),
    .restart    (restart),
    .count      (count),
    .step       (step),
    .up         (up),
    .caught_up  (caught_up)
  );

  reg placed;   // the count has caught up with the position since reset
  reg a_reg, b_reg, i_reg;
  always @(posedge clk) begin
    if (caught_up) begin
      placed <= 1'b1;
    end
    a_reg <= count[1] ^ count[0];
    b_reg <= count[1];
    i_reg <= placed & (count == {SB{1'b0}});
    if (rst || restart) begin
      placed <= 1'b0;
      a_reg  <= 1'b0;
      b_reg  <= 1'b0;
      i_reg  <= 1'b0;
    end
  end

  assign a = a_reg;
  assign b = b_reg;
  assign i = i_reg;

  wire unused_ok = &{1'b0, step, up, settings1[7:6], settings1[4:0], settings2[2:0],
                     steps_32[31:SB]};

endmodule

`resetall
