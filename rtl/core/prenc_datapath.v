// SPDX-License-Identifier: Apache-2.0
// prenc_datapath: the reader's datapath from the pins to the checked code word.
//
//   head1, head2, sync_a, sync_b
//     -> prenc_input_conditioner (synchronizers, glitch filters)
//     -> prenc_quadrature        (quarter, steps, illegal transitions, step count)
//     -> prenc_sampler           (mid-slot strobes, head readings)
//     -> prenc_shift_register    (the main code word W(p), flushed on an illegal step)
//     -> prenc_predictor         (what each head must read, per-head mismatch)
//
// Until the word is full it is formed from the leading head's raw readings. Once it
// is full it advances by the disc's law (the predicted bits) and the heads only
// check it: a misread is flagged but never enters the word. `flush` (from the mode
// state machine) empties it, to form it again from the heads.
//
// The same chain is modelled stage for stage by prenc.datapath.Datapath.
// Hold rst for at least 4 clocks (see prenc_quadrature).
//
// Parameters
//   N            code word length, 2..24
//   TAPS         feedback set as a mask, bit t-1 per tap t (default disc: 32'h204)
//   FILTER       glitch filter length in clocks, 0 (off)..65535
//   COUNT_WIDTH  signed step counter width, 2..64
//   ERROR_WIDTH  illegal-transition counter width, 1..32
//
// Ports: the pins, clear_errors, flush, and each stage's outputs (see the stage's
// file). check_now, mismatch1_now, mismatch2_now are the checks of the strobe on
// this clock (combinational); check, mismatch1, mismatch2 are the same registered.

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_datapath #(
  parameter integer N           = 10,
  parameter [31:0]  TAPS        = 32'h0000_0204,
  parameter integer FILTER      = 2,
  parameter integer COUNT_WIDTH = 32,
  parameter integer ERROR_WIDTH = 16
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   head1,
  input  wire                   head2,
  input  wire                   sync_a,
  input  wire                   sync_b,
  input  wire                   clear_errors,
  input  wire                   flush,
  // quadrature
  output wire [1:0]             quarter,
  output wire                   step,
  output wire                   step_cw,
  output wire                   illegal,
  output wire [ERROR_WIDTH-1:0] illegal_count,
  output wire [COUNT_WIDTH-1:0] step_count,
  // sampling
  output wire                   strobe,
  output wire                   strobe_cw,
  output wire                   strobe_moved,
  output wire                   strobe_head1,
  output wire                   strobe_head2,
  // code word
  output wire [N-1:0]           word,
  output wire [N-1:0]           word_known,
  output wire [$clog2(N+1)-1:0] word_count,
  output wire                   word_full,
  // prediction
  output wire                   predict1,
  output wire                   predict2,
  output wire                   check_now,
  output wire                   mismatch1_now,
  output wire                   mismatch2_now,
  output wire                   check,
  output wire                   expect1,
  output wire                   expect2,
  output wire                   mismatch1,
  output wire                   mismatch2
);

  wire [3:0] clean;  // {B, A, head2, head1}

  prenc_input_conditioner #(
    .WIDTH  (4),
    .FILTER (FILTER)
  ) u_input_conditioner (
    .clk      (clk),
    .rst      (rst),
    .in_raw   ({sync_b, sync_a, head2, head1}),
    .in_clean (clean)
  );

  wire [1:0] quarter_next;
  wire       step_next;
  wire       step_cw_next;
  wire       illegal_next;

  prenc_quadrature #(
    .COUNT_WIDTH (COUNT_WIDTH),
    .ERROR_WIDTH (ERROR_WIDTH)
  ) u_quadrature (
    .clk           (clk),
    .rst           (rst),
    .a             (clean[2]),
    .b             (clean[3]),
    .clear_errors  (clear_errors),
    .quarter       (quarter),
    .step          (step),
    .step_cw       (step_cw),
    .illegal       (illegal),
    .illegal_count (illegal_count),
    .count         (step_count),
    .quarter_next  (quarter_next),  // the datapath takes the registered step
    .step_next     (step_next),
    .step_cw_next  (step_cw_next),
    .illegal_next  (illegal_next)
  );

  wire unused_next = &{1'b0, quarter_next, step_next, step_cw_next, illegal_next};

  prenc_sampler u_sampler (
    .clk          (clk),
    .rst          (rst),
    .head1_in     (clean[0]),
    .head2_in     (clean[1]),
    .step         (step),
    .step_cw      (step_cw),
    .quarter      (quarter),
    .break_in     (illegal),
    .strobe       (strobe),
    .strobe_cw    (strobe_cw),
    .strobe_moved (strobe_moved),
    .strobe_head1 (strobe_head1),
    .strobe_head2 (strobe_head2)
  );

  // Raw readings until the word is full, the law after.
  wire fill1 = word_full ? predict1 : strobe_head1;
  wire fill2 = word_full ? predict2 : strobe_head2;

  assign check_now     = strobe & word_full;
  assign mismatch1_now = check_now & (strobe_head1 != predict1);
  assign mismatch2_now = check_now & (strobe_head2 != predict2);

  prenc_shift_register #(
    .N (N)
  ) u_shift_register (
    .clk          (clk),
    .rst          (rst),
    .flush        (illegal | flush),
    .strobe       (strobe),
    .strobe_cw    (strobe_cw),
    .strobe_moved (strobe_moved),
    .strobe_head1 (fill1),
    .strobe_head2 (fill2),
    .word         (word),
    .known        (word_known),
    .count        (word_count),
    .full         (word_full)
  );

  prenc_predictor #(
    .N    (N),
    .TAPS (TAPS)
  ) u_predictor (
    .clk          (clk),
    .rst          (rst),
    .strobe       (strobe),
    .strobe_cw    (strobe_cw),
    .strobe_moved (strobe_moved),
    .strobe_head1 (strobe_head1),
    .strobe_head2 (strobe_head2),
    .word         (word),
    .full         (word_full),
    .predict1     (predict1),
    .predict2     (predict2),
    .check        (check),
    .expect1      (expect1),
    .expect2      (expect2),
    .mismatch1    (mismatch1),
    .mismatch2    (mismatch2)
  );

endmodule

`resetall
