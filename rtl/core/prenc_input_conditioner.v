// SPDX-License-Identifier: Apache-2.0
// prenc_input_conditioner: synchronizers and glitch filters for asynchronous inputs.
//
// Each input bit goes through a two-flop synchronizer, then a glitch filter: a new
// level reaches the output only after the synchronized input has shown it on
// FILTER consecutive clocks, so a pulse shorter than FILTER clocks never passes.
//
// With PAIRED = 1 the top two inputs are a quadrature pair (A, B), filtered as one
// two-bit state: a new (A, B) reaches the output only after the synchronized inputs
// have shown that state on FILTER consecutive clocks. A and B changing fewer than
// FILTER clocks apart, in either order, therefore reach the output together: a
// missed state to the quadrature decoder, never two steps. (Two synchronizers can
// resolve one change of both a clock apart in either order, and bounce can spread
// them further; two separate filters would pass them as two steps, the wrong way
// round half the time: a slot off.) Alone on its clock, an edge of A or B passes
// exactly as through its own filter.
//
// Latency from a clean input edge: 2 clocks (synchronizer), plus FILTER clocks when
// FILTER > 0. FILTER = 0 turns the filter off (the synchronizer output directly).
//
// Parameters
//   WIDTH    number of inputs, >= 1 (the reader uses 4: head1, head2, A, B)
//   FILTER   filter length in clocks, 0..65535
//   PAIRED   1: inputs WIDTH-1 and WIDTH-2 are filtered as one state (needs WIDTH >= 2)
//
// Ports
//   clk, rst   one clock; synchronous active-high reset. During reset the filter
//              output loads the synchronized input: it holds the true input level
//              from the third reset clock on, so a logic that loads its start state
//              from in_clean during reset needs rst for at least 4 clocks.
//   in_raw     asynchronous inputs
//   in_clean   synchronized, filtered inputs

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_input_conditioner #(
  parameter integer WIDTH  = 4,
  parameter integer FILTER = 2,
  parameter integer PAIRED = 0
) (
  input  wire             clk,
  input  wire             rst,
  input  wire [WIDTH-1:0] in_raw,
  output wire [WIDTH-1:0] in_clean
);

  generate
    if (WIDTH < 1) begin : g_bad_width
      initial $display("ERROR: %m: parameter WIDTH = %0d must be at least 1", WIDTH);
      prenc_input_conditioner_parameter_WIDTH_below_1 u_stop ();
    end
    if (FILTER < 0 || FILTER > 65535) begin : g_bad_filter
      initial $display("ERROR: %m: parameter FILTER = %0d is out of range 0..65535", FILTER);
      prenc_input_conditioner_parameter_FILTER_out_of_range_0_to_65535 u_stop ();
    end
    if (PAIRED != 0 && PAIRED != 1) begin : g_bad_paired
      initial $display("ERROR: %m: parameter PAIRED = %0d must be 0 or 1", PAIRED);
      prenc_input_conditioner_parameter_PAIRED_must_be_0_or_1 u_stop ();
    end
    if (PAIRED == 1 && WIDTH < 2) begin : g_bad_paired_width
      initial $display("ERROR: %m: parameter PAIRED = 1 needs WIDTH >= 2, not %0d", WIDTH);
      prenc_input_conditioner_parameter_PAIRED_needs_WIDTH_2 u_stop ();
    end
  endgenerate

  // Two-flop synchronizer, written as one visible shift.
  reg [WIDTH-1:0] sync_q1;
  reg [WIDTH-1:0] sync_q2;

  always @(posedge clk) begin
    {sync_q2, sync_q1} <= {sync_q1, in_raw};
  end

  generate
    if (FILTER == 0) begin : g_no_filter
      wire unused_rst = rst;  // nothing to reset without a filter
      assign in_clean = sync_q2;
    end else begin : g_filter
      localparam integer  CW     = (FILTER < 2) ? 1 : $clog2(FILTER);
      localparam [31:0]   LAST32 = FILTER - 1;
      localparam [CW-1:0] LAST   = LAST32[CW-1:0];

      localparam integer SINGLE = (PAIRED == 1) ? WIDTH - 2 : WIDTH;  // filtered alone
      genvar i;
      for (i = 0; i < SINGLE; i = i + 1) begin : g_bit
        reg [CW-1:0] count_reg;  // clocks the input has differed from the output
        reg          level_reg;

        always @(posedge clk) begin
          if (sync_q2[i] == level_reg) begin
            count_reg <= {CW{1'b0}};
          end else if (count_reg == LAST) begin
            count_reg <= {CW{1'b0}};
            level_reg <= sync_q2[i];
          end else begin
            count_reg <= count_reg + 1'b1;
          end
          if (rst) begin
            count_reg <= {CW{1'b0}};
            level_reg <= sync_q2[i];
          end
        end

        assign in_clean[i] = level_reg;
      end
      if (PAIRED == 1) begin : g_pair
        wire [1:0]   pair_in = sync_q2[WIDTH-1:WIDTH-2];
        reg  [1:0]   prev_reg;   // the synchronized pair a clock earlier
        reg  [CW-1:0] count_reg;  // clocks the pair has shown its state, differing from the output
        reg  [1:0]   level_reg;
        // Clocks the pair showed this state before this one; 0 for a new state.
        wire [CW-1:0] seen = (pair_in == prev_reg) ? count_reg : {CW{1'b0}};
        always @(posedge clk) begin
          prev_reg <= pair_in;
          if (pair_in == level_reg) begin
            count_reg <= {CW{1'b0}};
          end else if (seen == LAST) begin
            count_reg <= {CW{1'b0}};
            level_reg <= pair_in;
          end else begin
            count_reg <= seen + 1'b1;
          end
          if (rst) begin
            count_reg <= {CW{1'b0}};
            level_reg <= pair_in;
          end
        end
        assign in_clean[WIDTH-1:WIDTH-2] = level_reg;
      end
    end
  endgenerate

`ifdef FORMAL
  // Properties (formal/prenc_input_conditioner.sby). f_raw_hist[k] is in_raw as it was
  // sampled k clocks ago; f_rst_now is rst at the last clock edge.
  localparam integer HIST = FILTER + 3;
  reg             f_past_valid = 1'b0;
  reg [WIDTH-1:0] f_raw_hist [0:HIST-1];
  reg             f_rst_now;
  reg [WIDTH-1:0] f_out_prev;
  reg [7:0]       f_steps = 8'd0;  // clocks since the start (saturating): history valid
  integer f_k;
  integer f_b;
  always @(posedge clk) begin
    f_past_valid  <= 1'b1;
    f_raw_hist[0] <= in_raw;
    for (f_k = 1; f_k < HIST; f_k = f_k + 1) begin
      f_raw_hist[f_k] <= f_raw_hist[f_k - 1];
    end
    f_rst_now  <= rst;
    f_out_prev <= in_clean;
    if (f_steps != 8'hFF) f_steps <= f_steps + 8'd1;
  end
  initial assume (rst);
  reg [WIDTH-1:0] f_steady;  // the FILTER samples that ended two clocks ago are equal
  always @(*) begin
    for (f_b = 0; f_b < WIDTH; f_b = f_b + 1) begin
      f_steady[f_b] = 1'b1;
      for (f_k = 3; f_k < FILTER + 2; f_k = f_k + 1) begin
        if (f_raw_hist[f_k][f_b] != f_raw_hist[2][f_b]) begin
          f_steady[f_b] = 1'b0;
        end
      end
    end
  end
  // The pair's bits, and whether both were steady.
  localparam integer F_LOW = (WIDTH >= 2) ? WIDTH - 2 : 0;  // the pair's low bit
  wire [WIDTH-1:0] f_paired = (PAIRED == 1) ? ({WIDTH{1'b1}} << F_LOW) : {WIDTH{1'b0}};
  wire             f_pair_steady = &(f_steady | ~f_paired);
  wire [1:0]       f_pair_out = in_clean >> F_LOW;
  wire [1:0]       f_pair_prev = f_out_prev >> F_LOW;
  reg  [1:0]       f_hist_pair;
  // The pair's input on the first of the FILTER samples the output shows, and before it.
  wire [1:0]       f_pair_in_first = f_raw_hist[FILTER + 1] >> F_LOW;
  wire [1:0]       f_pair_in_before = f_raw_hist[FILTER + 2] >> F_LOW;
  always @(*) begin
    if (f_steps >= HIST) begin
      // During reset the output loads the synchronized input (two samples ago).
      if (f_rst_now) assert (in_clean == f_raw_hist[2]);
      for (f_b = 0; f_b < WIDTH; f_b = f_b + 1) begin
        // No pulse shorter than FILTER clocks passes, reset or not: a new output level
        // was on the input for the FILTER samples that ended two clocks ago.
        if (!f_rst_now && in_clean[f_b] != f_out_prev[f_b]) begin
          for (f_k = 2; f_k < FILTER + 2; f_k = f_k + 1) begin
            assert (f_raw_hist[f_k][f_b] == in_clean[f_b]);
          end
        end
        // The output follows a steady input within 2 + FILTER clocks: after FILTER
        // equal samples (ending two clocks ago) the output shows them (a bit of the
        // pair: when both of its bits are steady).
        if (f_steady[f_b] && !(f_paired[f_b] && !f_pair_steady)) begin
          assert (in_clean[f_b] == f_raw_hist[2][f_b]);
        end
      end
      // The pair changes only to a state both its inputs showed together on the
      // FILTER samples that ended two clocks ago: A and B changing fewer than FILTER
      // clocks apart come out together.
      if (PAIRED == 1 && !f_rst_now && f_pair_out != f_pair_prev) begin
        for (f_k = 2; f_k < FILTER + 2; f_k = f_k + 1) begin
          f_hist_pair = f_raw_hist[f_k] >> F_LOW;
          assert (f_hist_pair == f_pair_out);
        end
      end
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (in_clean[0] != f_out_prev[0]);  // an edge passes
      cover (f_raw_hist[2][0] != in_clean[0] && f_raw_hist[3][0] == in_clean[0]);  // a glitch
      // The pair's two bits change together, their inputs a clock apart.
      if (PAIRED == 1) begin
        cover (f_pair_out == ~f_pair_prev && (f_pair_in_first ^ f_pair_in_before) != 2'b11 &&
               f_pair_in_first != f_pair_in_before);
      end
    end
  end
`endif

endmodule

`resetall
