// SPDX-License-Identifier: Apache-2.0
// prenc_edge_capture: the sync track's edges as the disc crosses them, with the clocks
// between them, for a calibration run over the host link (docs/calibration.md).
//
// Each step of the quadrature decoder crosses an edge: clockwise into quarter q the
// edge q, counter-clockwise into q the edge q + 1. The core's pos_hyb follows its step
// by POS_LAG = 4 clocks, so the block takes the step, its direction and an illegal
// transition POS_LAG clocks late, when pos_hyb is q (and pos_valid says whether it is
// valid). An entry {pos_valid, direction, edge, interval} goes into a FIFO of DEPTH = 4
// entries; interval is the clocks since the step before, saturating at 65535.
// The head of the FIFO is offered as a run: up to three entries in a row that are
// consecutive edges one way with pos_valid (run 1 for any other head). `take` (the
// host link's answer starts) removes the run. `lost` says that since the last take an
// entry found the FIFO full and was dropped, or an illegal transition (a missed state)
// came: the record has a gap there, and the host starts it anew.
// Model: prenc.cal.edge_capture.EdgeCapture.
//
// Latency: a step's entry is written into the FIFO POS_LAG + 1 clocks after the step;
// the run at the FIFO's head is on the outputs from the clock after it was written,
// until `take` removes it.
//
// Parameters
//   N   code word length, 2..24 (edges are N + 2 bits)
//
// Ports
//   step, step_cw, illegal, pos_hyb, pos_valid   the core's (sync_step, direction,
//                                                sync_illegal)
//   take            one clock: the run is taken
//   run             entries in the run, 0..3
//   run_valid       pos_valid held at the run's steps
//   run_cw          the run's direction
//   run_edge        the run's first edge
//   interval0..2    the run's intervals (0 past its end)
//   lost            an entry dropped or an illegal transition since the last take (one
//                   clock after it)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_edge_capture #(
  parameter integer N = 10
) (
  input  wire         clk,
  input  wire         rst,
  input  wire         step,
  input  wire         step_cw,
  input  wire         illegal,
  input  wire [N+1:0] pos_hyb,
  input  wire         pos_valid,
  input  wire         take,
  output wire [1:0]   run,
  output wire         run_valid,
  output wire         run_cw,
  output wire [N+1:0] run_edge,
  output wire [15:0]  interval0,
  output wire [15:0]  interval1,
  output wire [15:0]  interval2,
  output wire         lost
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_edge_capture_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  localparam integer EB = N + 2;          // an edge
  localparam integer WB = EB + 19;        // an entry: {continues, valid, cw, edge, interval}

  // The step, its direction and an illegal transition, POS_LAG clocks late.
  localparam integer POS_LAG = 4;

  reg  [POS_LAG-1:0] step_d_reg;
  reg  [POS_LAG-1:0] cw_d_reg;
  reg  [POS_LAG-1:0] illegal_d_reg;
  wire               step_late    = step_d_reg[POS_LAG-1];
  wire               cw_late      = cw_d_reg[POS_LAG-1];
  wire               illegal_late = illegal_d_reg[POS_LAG-1];

  // Stage 1: the step, registered with its quarter and interval.
  reg          step_reg;
  reg          cw_reg;
  reg          valid_reg;
  reg          illegal_reg;
  reg [N+1:0]  quarter_reg;
  reg [15:0]   interval_reg;
  reg [15:0]   since_reg;      // clocks since the last step, less one (saturating)
  // Stage 2: the FIFO, head first (registers: Yosys would read an array as a memory),
  // and the last entry pushed, which the next one may continue.
  reg [WB-1:0] e0_reg;
  reg [WB-1:0] e1_reg;
  reg [WB-1:0] e2_reg;
  reg [WB-1:0] e3_reg;
  reg [2:0]    count_reg;
  reg          lost_reg;
  reg [EB-1:0] last_edge_reg;
  reg          last_cw_reg;
  reg          last_valid_reg;

  wire [EB-1:0] edge_now  = cw_reg ? quarter_reg : quarter_reg + 1'b1;
  wire [EB-1:0] following = last_cw_reg ? last_edge_reg + 1'b1 : last_edge_reg - 1'b1;
  wire          continues = valid_reg && last_valid_reg && (cw_reg == last_cw_reg) &&
                            (edge_now == following);
  wire [WB-1:0] entry     = {continues, valid_reg, cw_reg, edge_now, interval_reg};

  // The run at the head: the entries that continue it, up to three.
  wire          ok0   = e0_reg[WB-2];
  wire          cw0   = e0_reg[WB-3];
  wire [EB-1:0] edge0 = e0_reg[EB+15:16];
  wire          join1 = (count_reg >= 3'd2) && e1_reg[WB-1];
  wire          join2 = join1 && (count_reg >= 3'd3) && e2_reg[WB-1];
  wire [1:0]    run_n = (count_reg == 3'd0) ? 2'd0 : join2 ? 2'd3 : join1 ? 2'd2 : 2'd1;
  wire [2:0]    taken = take ? {1'b0, run_n} : 3'd0;
  wire [2:0]    left  = count_reg - taken;       // entries that stay
  wire          full  = (left == 3'd4);
  wire          push  = step_reg && !full;

  // The FIFO after the take, then with the new entry behind what stays.
  reg [WB-1:0] s0;
  reg [WB-1:0] s1;
  reg [WB-1:0] s2;
  reg [WB-1:0] s3;
  always @(*) begin
    s0 = e0_reg;
    s1 = e1_reg;
    s2 = e2_reg;
    s3 = e3_reg;
    case (taken)
      3'd1: begin s0 = e1_reg; s1 = e2_reg; s2 = e3_reg; end
      3'd2: begin s0 = e2_reg; s1 = e3_reg; end
      3'd3: begin s0 = e3_reg; end
      default: begin end
    endcase
    if (push) begin
      case (left)
        3'd0: s0 = entry;
        3'd1: s1 = entry;
        3'd2: s2 = entry;
        default: s3 = entry;
      endcase
    end
  end

  always @(posedge clk) begin
    step_d_reg    <= {step_d_reg[POS_LAG-2:0], step};
    cw_d_reg      <= {cw_d_reg[POS_LAG-2:0], step_cw};
    illegal_d_reg <= {illegal_d_reg[POS_LAG-2:0], illegal};
    step_reg     <= step_late;
    cw_reg       <= cw_late;
    valid_reg    <= pos_valid;
    illegal_reg  <= illegal_late;
    quarter_reg  <= pos_hyb;
    interval_reg <= (since_reg == 16'hFFFF) ? 16'hFFFF : since_reg + 16'd1;
    since_reg    <= step_late ? 16'd0 : (since_reg == 16'hFFFF) ? since_reg : since_reg + 16'd1;
    e0_reg       <= s0;
    e1_reg       <= s1;
    e2_reg       <= s2;
    e3_reg       <= s3;
    count_reg    <= left + (push ? 3'd1 : 3'd0);
    lost_reg     <= (lost_reg && !take) || illegal_reg || (step_reg && full);
    if (push) begin
      last_edge_reg  <= edge_now;
      last_cw_reg    <= cw_reg;
      last_valid_reg <= valid_reg;
    end
    if (rst) begin
      step_d_reg     <= {POS_LAG{1'b0}};
      cw_d_reg       <= {POS_LAG{1'b0}};
      illegal_d_reg  <= {POS_LAG{1'b0}};
      step_reg       <= 1'b0;
      cw_reg         <= 1'b0;
      valid_reg      <= 1'b0;
      illegal_reg    <= 1'b0;
      quarter_reg    <= {EB{1'b0}};
      interval_reg   <= 16'd0;
      since_reg      <= 16'hFFFF;
      e0_reg         <= {WB{1'b0}};
      e1_reg         <= {WB{1'b0}};
      e2_reg         <= {WB{1'b0}};
      e3_reg         <= {WB{1'b0}};
      count_reg      <= 3'd0;
      lost_reg       <= 1'b0;
      last_edge_reg  <= {EB{1'b0}};
      last_cw_reg    <= 1'b0;
      last_valid_reg <= 1'b0;
    end
  end

  assign run       = run_n;
  assign run_valid = ok0 && (count_reg != 3'd0);
  assign run_cw    = cw0;
  assign run_edge  = edge0;
  assign interval0 = (count_reg != 3'd0) ? e0_reg[15:0] : 16'd0;
  assign interval1 = join1 ? e1_reg[15:0] : 16'd0;
  assign interval2 = join2 ? e2_reg[15:0] : 16'd0;
  assign lost      = lost_reg;

endmodule

`resetall
