// SPDX-License-Identifier: Apache-2.0
// prenc_core_harness: prenc_core with few pins, for place and route on small packages
// (iCE40 UP5K SG48, 39 I/O; the core has 141 output bits at N = 10).
//
// The core's inputs are pins. Every output bit is XORed, four to a LUT, into a register,
// and those registers fold the same way, stage by stage, into one pin, so that nothing
// of the core can be optimized away. Each core output reaches a register through one
// LUT, as it would reach a user's register. What the harness adds (about 40 LC on
// iCE40: the first stage and the fold) is measured beside the core alone in
// `make bench`. Used by `scripts/synth.py --core <target> --top prenc_core_harness`;
// not for designs.
//
// Latency: the core's, plus the registers that fold its outputs into one pin; the
// harness exists for synthesis only.
//
// Parameters: N, TAPS, FILTER, ROM_FILE as prenc_core (checked there); the core's other
// parameters keep their defaults.

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_core_harness #(
  parameter integer N        = 10,
  parameter [31:0]  TAPS     = 32'h0000_0204,
  parameter integer FILTER   = 2,
  parameter         ROM_FILE = "prenc_rom_n10.hex"
) (
  input  wire clk,
  input  wire rst,
  input  wire head1,
  input  wire head2,
  input  wire sync_a,
  input  wire sync_b,
  input  wire resolution,
  input  wire clear_errors,
  output reg  probe
);

  localparam integer COUNT_WIDTH = 32;
  localparam integer ERROR_WIDTH = 16;
  // Output bits, then each fold stage's registers: four bits to one, the last LUT of a
  // stage padded with at least one zero (one more register than needed when the bits
  // divide by four; Yosys removes it as constant).
  localparam integer W0 = 5 * N + 4 + 11 + COUNT_WIDTH + 3 * ERROR_WIDTH;
  localparam integer W1 = W0 / 4 + 1;
  localparam integer W2 = W1 / 4 + 1;
  localparam integer W3 = W2 / 4 + 1;  // <= 4 for N <= 24

  wire [N-1:0]           pos_abs;
  wire [N+1:0]           pos_hyb;
  wire                   pos_valid;
  wire [2:0]             mode;
  wire [N+1:0]           position;
  wire [COUNT_WIDTH-1:0] incremental;
  wire                   direction;
  wire [N-1:0]           track1_pos;
  wire                   track1_valid;
  wire [N-1:0]           track2_pos;
  wire                   track2_valid;
  wire [ERROR_WIDTH-1:0] track1_errors;
  wire [ERROR_WIDTH-1:0] track2_errors;
  wire [ERROR_WIDTH-1:0] sync_errors;
  wire                   track1_error;
  wire                   track2_error;
  wire                   sync_step;
  wire                   sync_illegal;

  prenc_core #(
    .N           (N),
    .TAPS        (TAPS),
    .FILTER      (FILTER),
    .ROM_FILE    (ROM_FILE),
    .COUNT_WIDTH (COUNT_WIDTH),
    .ERROR_WIDTH (ERROR_WIDTH)
  ) u_core (
    .clk           (clk),
    .rst           (rst),
    .head1         (head1),
    .head2         (head2),
    .sync_a        (sync_a),
    .sync_b        (sync_b),
    .resolution    (resolution),
    .clear_errors  (clear_errors),
    .pos_abs       (pos_abs),
    .pos_hyb       (pos_hyb),
    .pos_valid     (pos_valid),
    .mode          (mode),
    .position      (position),
    .incremental   (incremental),
    .direction     (direction),
    .track1_pos    (track1_pos),
    .track1_valid  (track1_valid),
    .track2_pos    (track2_pos),
    .track2_valid  (track2_valid),
    .track1_errors (track1_errors),
    .track2_errors (track2_errors),
    .sync_errors   (sync_errors),
    .track1_error  (track1_error),
    .track2_error  (track2_error),
    .sync_step     (sync_step),
    .sync_illegal  (sync_illegal)
  );

  wire [W0-1:0] outputs = {pos_abs, pos_hyb, pos_valid, mode, position, incremental, direction,
                           track1_pos, track1_valid, track2_pos, track2_valid,
                           track1_errors, track2_errors, sync_errors, track1_error, track2_error,
                           sync_step, sync_illegal};

  reg  [W1-1:0]   stage1;
  reg  [W2-1:0]   stage2;
  reg  [W3-1:0]   stage3;
  wire [4*W1-1:0] in1 = {{(4 * W1 - W0){1'b0}}, outputs};
  wire [4*W2-1:0] in2 = {{(4 * W2 - W1){1'b0}}, stage1};
  wire [4*W3-1:0] in3 = {{(4 * W3 - W2){1'b0}}, stage2};
  genvar g;
  generate
    for (g = 0; g < W1; g = g + 1) begin : g_fold1
      always @(posedge clk) stage1[g] <= ^in1[4*g+3:4*g];
    end
    for (g = 0; g < W2; g = g + 1) begin : g_fold2
      always @(posedge clk) stage2[g] <= ^in2[4*g+3:4*g];
    end
    for (g = 0; g < W3; g = g + 1) begin : g_fold3
      always @(posedge clk) stage3[g] <= ^in3[4*g+3:4*g];
    end
  endgenerate

  always @(posedge clk) begin
    probe <= ^stage3;
  end

endmodule

`resetall
