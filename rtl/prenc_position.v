// SPDX-License-Identifier: Apache-2.0
// prenc_position: the slot count, the reader's events, and the count delayed to
// meet the judge's decision.
//
// From the quadrature decoder's registered step (clock t) it registers on t+1 the
// slot count and the event the rest of the core sees on that clock: `up` (a CW
// step into q = 0, a slot boundary), `down` (a CCW step into q = 3) or `illegal`.
// An illegal transition (A and B changed together) moved the disc two quarters;
// the count takes the pair of steps in the last legal direction (a slot when that
// crosses a boundary) and the judge keeps the other way open. The count and the
// quarter are also delayed DECISION_DELAY = 3 more clocks (slot_out, quarter_out),
// so that count + offset meets the judge's verdict at one latency.
// Model: prenc.position.Position.
//
// Parameters
//   N   code word length, 2..24 (the count is modulo 2^N)
//
// Ports
//   quarter, step, step_cw, illegal   from prenc_quadrature (step_cw holds the last
//                                     legal direction)
//   slot, up, down, ev_illegal, ev_illegal_cw   registered on t+1
//   slot_out, quarter_out             the same, three clocks later
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_position #(
  parameter integer N = 10
) (
  input  wire         clk,
  input  wire         rst,
  input  wire [1:0]   quarter,
  input  wire         step,
  input  wire         step_cw,
  input  wire         illegal,
  output wire [N-1:0] slot,
  output wire         up,
  output wire         down,
  output wire         ev_illegal,
  output wire         ev_illegal_cw,
  output wire [N-1:0] slot_out,
  output wire [1:0]   quarter_out
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_position_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  reg [N-1:0] slot_reg;
  reg [1:0]   quarter_reg;
  reg         up_reg;
  reg         down_reg;
  reg         illegal_reg;
  reg         illegal_cw_reg;
  reg [N-1:0] slot_d1_reg;
  reg [N-1:0] slot_d2_reg;
  reg [N-1:0] slot_d3_reg;
  reg [1:0]   quarter_d1_reg;
  reg [1:0]   quarter_d2_reg;
  reg [1:0]   quarter_d3_reg;

  wire move_up   = (step & step_cw & (quarter == 2'd0)) | (illegal & step_cw & ~quarter[1]);
  wire move_down = (step & ~step_cw & (quarter == 2'd3)) | (illegal & ~step_cw & quarter[1]);

  always @(posedge clk) begin
    {slot_d3_reg, slot_d2_reg, slot_d1_reg}          <= {slot_d2_reg, slot_d1_reg, slot_reg};
    {quarter_d3_reg, quarter_d2_reg, quarter_d1_reg} <=
        {quarter_d2_reg, quarter_d1_reg, quarter_reg};
    if (move_up) begin
      slot_reg <= slot_reg + 1'b1;
    end else if (move_down) begin
      slot_reg <= slot_reg - 1'b1;
    end
    quarter_reg    <= quarter;
    up_reg         <= move_up;
    down_reg       <= move_down;
    illegal_reg    <= illegal;
    illegal_cw_reg <= step_cw;
    if (rst) begin
      slot_reg       <= {N{1'b0}};
      quarter_reg    <= 2'd0;
      up_reg         <= 1'b0;
      down_reg       <= 1'b0;
      illegal_reg    <= 1'b0;
      slot_d1_reg    <= {N{1'b0}};
      slot_d2_reg    <= {N{1'b0}};
      slot_d3_reg    <= {N{1'b0}};
      quarter_d1_reg <= 2'd0;
      quarter_d2_reg <= 2'd0;
      quarter_d3_reg <= 2'd0;
    end
  end

  assign slot          = slot_reg;
  assign up            = up_reg;
  assign down          = down_reg;
  assign ev_illegal    = illegal_reg;
  assign ev_illegal_cw = illegal_cw_reg;
  assign slot_out      = slot_d3_reg;
  assign quarter_out   = quarter_d3_reg;

endmodule

`resetall
