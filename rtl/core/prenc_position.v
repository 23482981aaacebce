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
// quarter are also delayed DECISION_DELAY = 4 more clocks (slot_out, quarter_out),
// so that count + offset meets the judge's verdict at one latency.
// Model: prenc.position.Position.
//
// Latency: slot, up, down and the illegal events one clock after the decoder's
// registered step; slot_out and quarter_out DECISION_DELAY = 4 clocks later, to meet
// the judge's verdict.
//
// Parameters
//   N   code word length, 2..24 (the count is modulo 2^N)
//
// Ports
//   quarter, step, step_cw, illegal   from prenc_quadrature (step_cw holds the last
//                                     legal direction)
//   slot, up, down, ev_illegal, ev_illegal_cw   registered on t+1
//   slot_out, quarter_out             the same, four clocks later
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
  reg [N-1:0] slot_d4_reg;
  reg [1:0]   quarter_d1_reg;
  reg [1:0]   quarter_d2_reg;
  reg [1:0]   quarter_d3_reg;
  reg [1:0]   quarter_d4_reg;

  wire move_up   = (step & step_cw & (quarter == 2'd0)) | (illegal & step_cw & ~quarter[1]);
  wire move_down = (step & ~step_cw & (quarter == 2'd3)) | (illegal & ~step_cw & quarter[1]);

  always @(posedge clk) begin
    {slot_d4_reg, slot_d3_reg, slot_d2_reg, slot_d1_reg} <=
        {slot_d3_reg, slot_d2_reg, slot_d1_reg, slot_reg};
    {quarter_d4_reg, quarter_d3_reg, quarter_d2_reg, quarter_d1_reg} <=
        {quarter_d3_reg, quarter_d2_reg, quarter_d1_reg, quarter_reg};
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
      slot_d4_reg    <= {N{1'b0}};
      quarter_d1_reg <= 2'd0;
      quarter_d2_reg <= 2'd0;
      quarter_d3_reg <= 2'd0;
      quarter_d4_reg <= 2'd0;
    end
  end

  assign slot          = slot_reg;
  assign up            = up_reg;
  assign down          = down_reg;
  assign ev_illegal    = illegal_reg;
  assign ev_illegal_cw = illegal_cw_reg;
  assign slot_out      = slot_d4_reg;
  assign quarter_out   = quarter_d4_reg;

`ifdef FORMAL
  // Properties (formal/prenc_position.sby), on the registers after each clock: the
  // count in quarters (4 slot + q) follows the decoder one clock later, one quarter
  // per legal step in its direction and two in the last legal direction after an
  // illegal transition; an event is flagged exactly when the slot moves; the delayed
  // outputs are the count DECISION_DELAY = 4 clocks earlier.
  reg f_past_valid = 1'b0;
  reg f_rst_prev;
  reg [N+1:0] f_hyb_prev;
  reg         f_step_prev;
  reg         f_cw_prev;
  reg         f_illegal_prev;
  reg [1:0]   f_quarter_prev;
  always @(posedge clk) begin
    f_past_valid   <= 1'b1;
    f_rst_prev     <= rst;
    f_hyb_prev     <= {slot_reg, quarter_reg};
    f_step_prev    <= step;
    f_cw_prev      <= step_cw;
    f_illegal_prev <= illegal;
    f_quarter_prev <= quarter;
  end
  initial assume (rst);
  // The decoder's contract (formal/prenc_quadrature.sby): a step moves the quarter by
  // one in its direction, an illegal transition by two, otherwise it holds.
  always @(*) begin
    assume (!(step && illegal));
    if (f_past_valid && !f_rst_prev) begin
      if (step) assume (quarter == (step_cw ? quarter_reg + 1'b1 : quarter_reg - 1'b1));
      else if (illegal) assume (quarter == quarter_reg + 2'd2);
      else assume (quarter == quarter_reg);
    end
  end
  wire [N+1:0] f_hyb = {slot_reg, quarter_reg};
  reg  [N+1:0] f_hyb_d1;
  reg  [N+1:0] f_hyb_d2;
  reg  [N+1:0] f_hyb_d3;
  reg  [N+1:0] f_hyb_d4;
  reg  [2:0]   f_since_rst = 3'd0;
  always @(posedge clk) begin
    {f_hyb_d4, f_hyb_d3, f_hyb_d2, f_hyb_d1} <= {f_hyb_d3, f_hyb_d2, f_hyb_d1, f_hyb};
    f_since_rst <= rst ? 3'd0 : (f_since_rst == 3'd7) ? 3'd7 : f_since_rst + 1'b1;
  end
  always @(*) begin
    if (f_past_valid && f_rst_prev) assert (f_hyb == {N+2{1'b0}} && !up && !down && !ev_illegal);
    // The first clock out of reset loads the decoder's quarter; then it moves.
    if (f_since_rst >= 3'd2) begin
      if (f_step_prev) begin
        assert (f_hyb == (f_cw_prev ? f_hyb_prev + 1'b1 : f_hyb_prev - 1'b1));
      end else if (f_illegal_prev) begin
        assert (f_hyb == (f_cw_prev ? f_hyb_prev + 2'd2 : f_hyb_prev - 2'd2));
      end else begin
        assert (f_hyb == f_hyb_prev);
      end
      assert (up == (slot_reg == f_hyb_prev[N+1:2] + 1'b1) && (up || down || !ev_illegal ||
              slot_reg == f_hyb_prev[N+1:2]));
      assert (down == (slot_reg == f_hyb_prev[N+1:2] - 1'b1));
      assert (ev_illegal == f_illegal_prev && ev_illegal_cw == f_cw_prev);
    end
    if (f_past_valid && !f_rst_prev) assert (quarter_reg == f_quarter_prev);
    if (f_since_rst >= 3'd4) assert ({slot_out, quarter_out} == f_hyb_d4);
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (up && ev_illegal);
      cover (down && ev_illegal);
      cover (slot_reg == {N{1'b1}} && quarter_reg == 2'd3);
    end
  end
`endif

endmodule

`resetall
