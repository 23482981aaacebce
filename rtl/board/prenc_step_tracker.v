// SPDX-License-Identifier: Apache-2.0
// prenc_step_tracker: the step a position is in, for a turn cut into `steps` equal steps,
// moved one step at a time so that a counter downstream of it sees every step (the
// ABI and UVW outputs: prenc_abi, prenc_uvw; docs/interfaces/abi-uvw.md).
//
// Step k of a turn (2^B positions) is [floor(k 2^B / S), floor((k + 1) 2^B / S)), S =
// `steps`. The tracker keeps its step `count` (0..S-1) and the step's lower edge
// exactly, as q = floor(2^B / S) and r = 2^B mod S taken k times (a remainder `rem`
// carries the fraction: no drift over any number of turns). While `valid`:
// - up one step when the position is at or past the step's upper edge, down one when it
//   is below the lower edge (positions compared modulo a turn: the shorter way);
// - hysteresis: after a step down, up again only `hysteresis` past the upper edge, and
//   after a step up, down again only `hysteresis` below the lower edge;
// - at most one step every `min_gap` clocks: a position that runs ahead is followed at
//   that rate, every step taken, none skipped.
// After reset or `restart` the count is 0 at the position 0 (the zero): the first valid
// position is reached by steps from there, so a counter that started with the tracker
// holds the absolute step (the shorter way round) once it has caught up (`caught_up`).
//
// Latency: a step is taken on the clock after the position crossed the edge (when
// min_gap allows it); `count` and `step` are registers. The edges and thresholds are
// registers too: a new hysteresis counts from the next step.
//
// Parameters
//   B            position bits, 2..32
//   STEPS_BITS   bits of `steps` and `count`, 2..24
//
// Ports
//   clk, rst         one clock; synchronous active-high reset
//   position, valid  the position (2^-B turn, the zero at 0) and its validity
//   steps, q, r      S (2..2^B), floor(2^B / S), 2^B mod S: registered, and a new S
//                    restarts the tracker on the next clock
//   hysteresis       in positions (2^-B turn), registered; it counts from the next step
//   min_gap          clocks from a step to the next, >= 1
//   restart          one clock: the tracker is back at count 0 at position 0 (the clock
//                    after reset, and after S changed)
//   count            the step, 0..S-1
//   step, up         one clock: a step was taken, upwards (1) or downwards (0)
//   caught_up        valid, and the count is the position's (no step pending)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_step_tracker #(
  parameter integer B          = 14,
  parameter integer STEPS_BITS = 13
) (
  input  wire                  clk,
  input  wire                  rst,
  input  wire [B-1:0]          position,
  input  wire                  valid,
  input  wire [STEPS_BITS-1:0] steps,
  input  wire [B-1:0]          q,
  input  wire [STEPS_BITS-1:0] r,
  input  wire [B-1:0]          hysteresis,
  input  wire [15:0]           min_gap,
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
    if (STEPS_BITS < 2 || STEPS_BITS > 24) begin : g_bad_steps_bits
      initial $display("ERROR: %m: parameter STEPS_BITS = %0d is out of range 2..24", STEPS_BITS);
      prenc_step_tracker_parameter_STEPS_BITS_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  localparam integer RB = STEPS_BITS + 1;   // the remainders' sums, before reduction

  // The settings, registered (they change when a register is written): S, q, r, the
  // hysteresis; a new S, and the reset, restart the tracker on the next clock.
  reg [STEPS_BITS-1:0] s_reg;
  reg [STEPS_BITS-1:0] s_last_reg;   // S - 1, the last step's count
  reg [B-1:0]          q_reg;
  reg [STEPS_BITS-1:0] r_reg;
  reg [B-1:0]          hyst_reg;
  reg                  restart_reg;
  always @(posedge clk) begin
    s_reg       <= steps;
    s_last_reg  <= steps - 1'b1;
    q_reg       <= q;
    r_reg       <= r;
    hyst_reg    <= hysteresis;
    restart_reg <= rst | (steps != s_reg);
  end

  // The step's edges and their remainders ((k 2^B) mod S), and the positions at which
  // the next step up or down is taken (the edges moved out by the hysteresis).
  reg [STEPS_BITS-1:0] count_reg;
  reg [B-1:0]          lower;
  reg [B-1:0]          upper;
  reg [STEPS_BITS-1:0] rem_lower;
  reg [STEPS_BITS-1:0] rem_upper;
  reg [B-1:0]          up_at;
  reg [B-1:0]          down_at;
  reg [15:0]           wait_left;   // clocks until a step may be taken
  reg                  step_reg;
  reg                  up_reg;

  // One step further up: the new upper edge; one step down: the new lower edge.
  wire [RB-1:0]         rem_sum     = {1'b0, rem_upper} + {1'b0, r_reg};
  wire                  carry       = (rem_sum >= {1'b0, s_reg});
  wire [STEPS_BITS-1:0] rem_above   = carry ? rem_sum[STEPS_BITS-1:0] - s_reg
                                            : rem_sum[STEPS_BITS-1:0];
  wire [B-1:0]          above       = upper + q_reg + {{(B - 1){1'b0}}, carry};
  wire                  borrow      = (rem_lower < r_reg);
  wire [STEPS_BITS-1:0] rem_below   = borrow ? rem_lower + s_reg - r_reg : rem_lower - r_reg;
  wire [B-1:0]          below       = lower - q_reg - {{(B - 1){1'b0}}, borrow};

  // Where the position is: past the thresholds, signed, modulo a turn.
  wire [B-1:0] past_up   = position - up_at;
  wire [B-1:0] past_down = position - down_at;
  wire         want_up   = ~past_up[B-1];
  wire         want_down = past_down[B-1];
  wire         may_step  = valid & (wait_left == 16'd0);
  wire         step_up   = may_step & want_up;
  wire         step_down = may_step & want_down & ~want_up;

  always @(posedge clk) begin
    step_reg <= step_up | step_down;
    up_reg   <= step_up;
    if (wait_left != 16'd0) begin
      wait_left <= wait_left - 16'd1;
    end
    if (step_up) begin
      count_reg <= (count_reg == s_last_reg) ? {STEPS_BITS{1'b0}} : count_reg + 1'b1;
      lower     <= upper;
      rem_lower <= rem_upper;
      upper     <= above;
      rem_upper <= rem_above;
      up_at     <= above;
      down_at   <= upper - hyst_reg;
      wait_left <= min_gap - 16'd1;
    end else if (step_down) begin
      count_reg <= (count_reg == {STEPS_BITS{1'b0}}) ? s_last_reg : count_reg - 1'b1;
      upper     <= lower;
      rem_upper <= rem_lower;
      lower     <= below;
      rem_lower <= rem_below;
      up_at     <= lower + hyst_reg;
      down_at   <= below;
      wait_left <= min_gap - 16'd1;
    end
    if (rst || restart_reg) begin
      count_reg <= {STEPS_BITS{1'b0}};
      lower     <= {B{1'b0}};
      rem_lower <= {STEPS_BITS{1'b0}};
      upper     <= q_reg;
      rem_upper <= r_reg;
      up_at     <= q_reg;
      down_at   <= {B{1'b0}};
      wait_left <= 16'd0;
      step_reg  <= 1'b0;
      up_reg    <= 1'b0;
    end
  end

  assign restart   = restart_reg;
  assign count     = count_reg;
  assign step      = step_reg;
  assign up        = up_reg;
  assign caught_up = valid & ~want_up & ~want_down;

endmodule

`resetall
