// SPDX-License-Identifier: Apache-2.0
// prenc_quadrature: quadrature decoder of the sync track.
//
// Maps (A, B) to the datasheet's quarter index q = 0..3 ((0,1), (0,0), (1,0), (1,1)),
// compares it with the previous clock's q and reports one of: no change, a legal
// step CW (q + 1 mod 4), a legal step CCW (q - 1 mod 4), or an illegal transition
// (q + 2: A and B changed together, a missed state). An illegal transition is
// never counted as a step; the decoder takes the new state and goes on.
//
// Errors are counted, not latched: illegal_count is a saturating counter cleared by
// clear_errors. A count tells the host how often, saturation keeps it from ever
// wrapping back to a harmless-looking zero, and the illegal pulse gives the event
// itself to the logic that must react at once.
//
// Latency: one clock: quarter, step, step_cw, illegal, the counts one clock after the
// (a, b) sample they describe; the *_next outputs on that sample's clock.
//
// Parameters
//   COUNT_WIDTH  width of the signed step counter, 2..64
//   ERROR_WIDTH  width of the illegal-transition counter, 1..32
//
// Reset loads the current (A, B) state without a step. Behind prenc_input_conditioner
// hold rst for at least 4 clocks (3 with FILTER = 0), so that the state it loads is
// the settled input and not the conditioner's start-up value.
//
// Ports (outputs are registered, one clock after the input they describe, but the
// *_next ones)
//   a, b           conditioned sync inputs
//   clear_errors   clears illegal_count (wins over a simultaneous illegal transition)
//   quarter        q of the current state
//   step           a legal transition happened; step_cw gives its direction
//   step_cw        1 for CW (q increased), 0 for CCW; holds the last step's direction
//   illegal        an illegal transition happened
//   illegal_count  illegal transitions since reset or clear_errors, saturating
//   count          CW steps minus CCW steps since reset (two's complement, wraps)
//   quarter_next, step_next, step_cw_next, illegal_next
//                  what quarter, step, step_cw and illegal take at this edge (out of
//                  reset), for a stage that registers the decoded step itself
//                  (prenc_core's sampler and position): a clock of latency less

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_quadrature #(
  parameter integer COUNT_WIDTH = 32,
  parameter integer ERROR_WIDTH = 16
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   a,
  input  wire                   b,
  input  wire                   clear_errors,
  output wire [1:0]             quarter,
  output wire                   step,
  output wire                   step_cw,
  output wire                   illegal,
  output wire [ERROR_WIDTH-1:0] illegal_count,
  output wire [COUNT_WIDTH-1:0] count,
  output wire [1:0]             quarter_next,
  output wire                   step_next,
  output wire                   step_cw_next,
  output wire                   illegal_next
);

  generate
    if (COUNT_WIDTH < 2 || COUNT_WIDTH > 64) begin : g_bad_count_width
      initial $display("ERROR: %m: parameter COUNT_WIDTH = %0d is out of range 2..64", COUNT_WIDTH);
      prenc_quadrature_parameter_COUNT_WIDTH_out_of_range_2_to_64 u_stop ();
    end
    if (ERROR_WIDTH < 1 || ERROR_WIDTH > 32) begin : g_bad_error_width
      initial $display("ERROR: %m: parameter ERROR_WIDTH = %0d is out of range 1..32", ERROR_WIDTH);
      prenc_quadrature_parameter_ERROR_WIDTH_out_of_range_1_to_32 u_stop ();
    end
  endgenerate

  // q = {A, A xnor B}: (0,1) -> 0, (0,0) -> 1, (1,0) -> 2, (1,1) -> 3.
  wire [1:0] q_in = {a, ~(a ^ b)};

  reg [1:0]             quarter_reg;
  reg                   step_reg;
  reg                   step_cw_reg;
  reg                   illegal_reg;
  reg [ERROR_WIDTH-1:0] illegal_count_reg;
  reg [COUNT_WIDTH-1:0] count_reg;

  wire [1:0] delta = q_in - quarter_reg;

  // The registers' next values, for the stages that take the step on the same edge
  // (out of reset: those stages reset themselves, and rst here would be a LUT level on
  // the path from the pins' registers).
  assign quarter_next = q_in;
  assign step_next    = delta[0];
  assign step_cw_next = (delta == 2'd1) | (step_cw_reg & (delta != 2'd3));
  assign illegal_next = (delta == 2'd2);

  always @(posedge clk) begin
    quarter_reg <= q_in;
    if (delta[0]) begin  // a step: +1 (delta 1) or -1 (delta 3), one adder for both
      count_reg <= count_reg + {{(COUNT_WIDTH - 1){delta[1]}}, 1'b1};
    end
    step_reg    <= 1'b0;
    illegal_reg <= 1'b0;
    case (delta)
      2'd1: begin
        step_reg    <= 1'b1;
        step_cw_reg <= 1'b1;
      end
      2'd3: begin
        step_reg    <= 1'b1;
        step_cw_reg <= 1'b0;
      end
      2'd2: begin
        illegal_reg <= 1'b1;
        if (illegal_count_reg != {ERROR_WIDTH{1'b1}}) begin
          illegal_count_reg <= illegal_count_reg + 1'b1;
        end
      end
      default: begin
      end
    endcase
    if (clear_errors) begin
      illegal_count_reg <= {ERROR_WIDTH{1'b0}};
    end
    if (rst) begin
      quarter_reg       <= q_in;  // start from the current state: no false step
      step_reg          <= 1'b0;
      step_cw_reg       <= 1'b1;
      illegal_reg       <= 1'b0;
      illegal_count_reg <= {ERROR_WIDTH{1'b0}};
      count_reg         <= {COUNT_WIDTH{1'b0}};
    end
  end

  assign quarter       = quarter_reg;
  assign step          = step_reg;
  assign step_cw       = step_cw_reg;
  assign illegal       = illegal_reg;
  assign illegal_count = illegal_count_reg;
  assign count         = count_reg;

`ifdef FORMAL
  // Properties (formal/prenc_quadrature.sby), on the registers after each clock.
  reg                   f_past_valid = 1'b0;
  reg [1:0]             f_q_prev;       // the quarter before this clock's input
  reg [COUNT_WIDTH-1:0] f_count_prev;
  reg                   f_rst_prev;
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_q_prev     <= quarter_reg;
    f_count_prev <= count_reg;
    f_rst_prev   <= rst;
  end
  initial assume (rst);
  wire [1:0] f_delta = quarter_reg - f_q_prev;  // what the last input did
  // The *_next outputs are what the registers take at the edge, out of reset.
  reg [4:0] f_next_prev;
  always @(posedge clk) f_next_prev <= {quarter_next, step_next, step_cw_next, illegal_next};
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      assert ({quarter_reg, step_reg, step_cw_reg, illegal_reg} == f_next_prev);
    end
  end
  // The quarter of the last input sample, from the datasheet's table (A, B) -> q:
  // (0, 1) 0, (0, 0) 1, (1, 0) 2, (1, 1) 3; and the error count's expected value.
  reg [1:0]             f_q_pins;
  reg                   f_clear_prev;
  reg [ERROR_WIDTH-1:0] f_errors_prev;
  always @(posedge clk) begin
    case ({a, b})
      2'b01:   f_q_pins <= 2'd0;
      2'b00:   f_q_pins <= 2'd1;
      2'b10:   f_q_pins <= 2'd2;
      default: f_q_pins <= 2'd3;
    endcase
    f_clear_prev  <= clear_errors;
    f_errors_prev <= illegal_count_reg;
  end
  always @(*) begin
    if (f_past_valid) begin
      assert (quarter_reg == f_q_pins);
      // Reset starts from the pins' state: no step, nothing illegal, count 0.
      if (f_rst_prev) assert (!step && !illegal && step_cw && count_reg == {COUNT_WIDTH{1'b0}});
      if (f_rst_prev || f_clear_prev) assert (illegal_count_reg == {ERROR_WIDTH{1'b0}});
      else if (illegal) assert (illegal_count_reg == ((f_errors_prev == {ERROR_WIDTH{1'b1}}) ?
                                                     f_errors_prev : f_errors_prev + 1'b1));
      else assert (illegal_count_reg == f_errors_prev);
    end
  end
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      // The count moves by at most one step a clock, exactly with a legal step.
      assert (count_reg == f_count_prev || count_reg == f_count_prev + 1'b1 ||
              count_reg == f_count_prev - 1'b1);
      assert (step == (f_delta == 2'd1 || f_delta == 2'd3));
      if (f_delta == 2'd1) assert (count_reg == f_count_prev + 1'b1 && step_cw);
      if (f_delta == 2'd3) assert (count_reg == f_count_prev - 1'b1 && !step_cw);
      // An illegal transition (A and B together) is flagged and never counted.
      assert (illegal == (f_delta == 2'd2));
      if (illegal) assert (count_reg == f_count_prev && !step);
      // No step, no change: the direction is the last legal step's.
      if (!step) assert (count_reg == f_count_prev);
    end
  end
  // The direction holds between steps.
  reg f_cw_prev;
  always @(posedge clk) f_cw_prev <= step_cw;
  always @(*) begin
    if (f_past_valid && !f_rst_prev && !step) assert (step_cw == f_cw_prev);
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (step && step_cw);
      cover (step && !step_cw);
      cover (illegal);
      cover (illegal_count_reg == 2);
    end
  end
`endif

endmodule

`resetall
