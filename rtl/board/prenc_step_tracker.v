// SPDX-License-Identifier: Apache-2.0
// prenc_step_tracker: the step a position is in, for a turn cut into `steps` equal steps,
// moved one step at a time so that a counter downstream of it sees every step (the
// ABI and UVW outputs: prenc_abi, prenc_uvw; docs/interfaces/abi-uvw.md).
//
// The position is taken at 16 bits (its top 16 bits; a narrower one widened): p, in
// 2^-16 turn. Step k of a turn of S = `steps` steps is the positions with
// floor(p S / 2^16) = k: one multiplication (a DSP block on the UP5K and the ECP5),
// exact, with no edges to keep and nothing to drift over any number of turns. The
// tracker keeps its step `count` (0..S-1) and, while `valid`, moves it towards the
// position's step, the shorter way round (half a turn: down):
// - hysteresis: after a step down, up again only when p less `hysteresis` is past the
//   upper edge; after a step up, down again only when p plus `hysteresis` is below the
//   lower edge (after a restart, neither);
// - at most one step every MIN_GAP clocks, and every 3 at least: a position that runs
//   ahead is followed at that rate, every step taken, none skipped.
// After reset or `restart` the count is 0 at the position 0 (the zero): the first valid
// position is reached by steps from there, so a counter that started with the tracker
// holds the absolute step (the shorter way round) once it has caught up (`caught_up`).
//
// Pipeline, a register a stage:
//   1  the step each threshold gives (`k_up`, `k_down`), from the position and the last
//      step's direction (a multiplication each), and `valid`;
//   2  whether the count is to go up or down (`want_up`, `want_down`): those steps
//      against the count, modulo S;
//   3  the step: `count`, `step`, `up`.
// A step's new count and hysteresis reach stage 2 two clocks later, and the next step
// waits for them (the 3 clocks at least); a restart clears the stages' `valid` (their
// steps are of the old S and direction).
//
// Latency: a step is taken 3 clocks after the position crossed the edge (when MIN_GAP
// allows it); `count` and `step` are registers. A new hysteresis counts from the next
// step.
//
// Parameters
//   B            position bits, 2..32
//   STEPS_BITS   bits of `steps` and `count`, 2..16
//   MIN_GAP      clocks from a step to the next, 1..65535 (3 are kept at least)
//
// Ports
//   clk, rst         one clock; synchronous active-high reset
//   position, valid  the position (2^-B turn, the zero at 0) and its validity
//   steps            S, 2..2^STEPS_BITS - 1: registered, and a new S restarts the tracker
//   hysteresis       in 2^-16 turn, registered; it counts from the next step
//   restart          one clock: the tracker is back at count 0 at position 0 (the clock
//                    after reset, and after S changed)
//   count            the step, 0..S-1
//   step, up         one clock: a step was taken, upwards (1) or downwards (0)
//   caught_up        the position 2 clocks before was valid, and the count then its step
//                    (no step pending)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_step_tracker #(
  parameter integer B          = 14,
  parameter integer STEPS_BITS = 13,
  parameter integer MIN_GAP    = 3
) (
  input  wire                  clk,
  input  wire                  rst,
  input  wire [B-1:0]          position,
  input  wire                  valid,
  input  wire [STEPS_BITS-1:0] steps,
  input  wire [15:0]           hysteresis,
  output wire                  restart,
  output wire [STEPS_BITS-1:0] count,
  output wire                  step,
  output wire                  up,
  output wire                  caught_up
);

  generate
    if (B < 2 || B > 32) begin : g_bad_b
      initial $display("ERROR: %m: parameter B = %0d is out of range 2..32", B);
      prenc_step_tracker_parameter_B_out_of_range_2_to_32 u_stop ();
    end
    if (STEPS_BITS < 2 || STEPS_BITS > 16) begin : g_bad_steps_bits
      initial $display("ERROR: %m: parameter STEPS_BITS = %0d is out of range 2..16", STEPS_BITS);
      prenc_step_tracker_parameter_STEPS_BITS_out_of_range_2_to_16 u_stop ();
    end
    if (MIN_GAP < 1 || MIN_GAP > 65535) begin : g_bad_min_gap
      initial $display("ERROR: %m: parameter MIN_GAP = %0d is out of range 1..65535", MIN_GAP);
      prenc_step_tracker_parameter_MIN_GAP_out_of_range_1_to_65535 u_stop ();
    end
  endgenerate

  localparam integer SB = STEPS_BITS;

  // The clocks a step waits after the one before, less one, and the bits that count them.
  localparam integer GAP_LEFT = (MIN_GAP < 3) ? 2 : MIN_GAP - 1;
  localparam integer WB       = $clog2(GAP_LEFT + 1);
  localparam [31:0]  GAP_32   = GAP_LEFT;
  localparam [WB-1:0] GAP     = GAP_32[WB-1:0];

  // The position at 16 bits.
  wire [15:0] p;
  generate
    if (B > 16) begin : g_top_bits
      assign p = position[B-1:B-16];
      wire unused_low = &{1'b0, position[B-17:0]};   // below 2^-16 turn
    end else if (B == 16) begin : g_all_bits
      assign p = position;
    end else begin : g_widened
      assign p = {position, {(16 - B){1'b0}}};
    end
  endgenerate

  // The settings, registered (they change when a register is written): S, S - 1, the
  // hysteresis; a new S, and the reset, restart the tracker on the next clock.
  reg [SB-1:0] s_reg;
  reg [SB-1:0] s_last_reg;   // S - 1, the last step's count
  reg [15:0]   hyst_reg;
  reg          restart_reg;
  always @(posedge clk) begin
    s_reg       <= steps;
    s_last_reg  <= steps - 1'b1;
    hyst_reg    <= hysteresis;
    restart_reg <= rst | (steps != s_reg);
  end

  reg [SB-1:0] count_reg;
  reg          last_up;      // the last step was up (0 after a restart)
  reg          last_down;    // the last step was down (0 after a restart)
  reg [WB-1:0] wait_left;    // clocks until a step may be taken
  reg          step_reg;
  reg          up_reg;

  // The thresholds, as steps: the step of p less the hysteresis (a step up needs it past
  // the count) and of p plus it (a step down needs it below).
  wire [15:0]      p_up     = p - (last_down ? hyst_reg : 16'd0);
  wire [15:0]      p_down   = p + (last_up ? hyst_reg : 16'd0);
  wire [SB+15:0]   k_up_p   = p_up * s_reg;
  wire [SB+15:0]   k_down_p = p_down * s_reg;
  reg  [SB-1:0]    k_up;
  reg  [SB-1:0]    k_down;
  reg              valid_d;
  always @(posedge clk) begin
    k_up    <= k_up_p[SB+15:16];
    k_down  <= k_down_p[SB+15:16];
    valid_d <= valid & ~(rst | restart_reg);
  end

  // Those steps against the count: the count goes the shorter way round, up when the
  // step is ahead by less than half a turn (modulo S), down when it is behind by half a
  // turn or less. With d the step less the count (-S < d < S), up is 0 < 2d < S or
  // 2d < -S; with e the count less the step, down is 0 < 2e <= S or 2e <= -S.
  wire signed [SB+2:0] s_signed     = {3'b000, s_reg};
  wire signed [SB+2:0] s_negative   = -s_signed;
  wire signed [SB+2:0] ahead        = {3'b000, k_up} - {3'b000, count_reg};
  wire signed [SB+2:0] behind       = {3'b000, count_reg} - {3'b000, k_down};
  wire signed [SB+2:0] ahead_twice  = ahead <<< 1;
  wire signed [SB+2:0] behind_twice = behind <<< 1;
  reg                  want_up;
  reg                  want_down;
  reg                  valid_dd;
  always @(posedge clk) begin
    want_up   <= (ahead > 0 && ahead_twice < s_signed) || ahead_twice < s_negative;
    want_down <= (behind > 0 && behind_twice <= s_signed) || behind_twice <= s_negative;
    valid_dd  <= valid_d & ~(rst | restart_reg);
  end

  wire          may_step  = valid_dd & (wait_left == {WB{1'b0}});
  wire          step_up   = may_step & want_up;
  wire          step_down = may_step & want_down & ~want_up;

  always @(posedge clk) begin
    step_reg <= step_up | step_down;
    up_reg   <= step_up;
    if (wait_left != {WB{1'b0}}) begin
      wait_left <= wait_left - 1'b1;
    end
    if (step_up) begin
      count_reg <= (count_reg == s_last_reg) ? {SB{1'b0}} : count_reg + 1'b1;
      last_up   <= 1'b1;
      last_down <= 1'b0;
      wait_left <= GAP;
    end else if (step_down) begin
      count_reg <= (count_reg == {SB{1'b0}}) ? s_last_reg : count_reg - 1'b1;
      last_up   <= 1'b0;
      last_down <= 1'b1;
      wait_left <= GAP;
    end
    if (rst || restart_reg) begin
      count_reg <= {SB{1'b0}};
      last_up   <= 1'b0;
      last_down <= 1'b0;
      wait_left <= {WB{1'b0}};
      step_reg  <= 1'b0;
      up_reg    <= 1'b0;
    end
  end

  wire unused_ok = &{1'b0, k_up_p[15:0], k_down_p[15:0]};   // the products' fractions

  assign restart   = restart_reg;
  assign count     = count_reg;
  assign step      = step_reg;
  assign up        = up_reg;
  assign caught_up = valid_dd & ~want_up & ~want_down;

endmodule

`resetall
