// prenc_core: the reader of a pseudorandom absolute encoder, pins to verified position.
//
//   pins -> prenc_datapath (conditioner, quadrature, sampler, shift register,
//                           predictor: the code word and both heads' checks)
//        -> prenc_converter (word -> slot, one clock)
//        -> prenc_position (slot count from the quadrature + offset from the ROM)
//        -> prenc_track_monitor x2 (how far each track confirms the position)
//        -> prenc_mode_fsm (modes; pos_valid)
// See docs/architecture.md for the block diagram, the modes and the timing.
//
// Start-up: the word needs N strobes (mid-slot crossings) at distinct slots; then
// both tracks must agree at 2N further consecutive slots (3N - 1 slots of movement
// in all), or one track at RUN_LONG slots when the other disagrees.
//
// Latency: pos_abs, pos_hyb and pos_valid show the pins as they were 3 + FILTER
// clocks earlier (FILTER = 0: 3 clocks). Hold rst for at least 4 clocks.
//
// Parameters
//   N            code word length, 2..24 (2^N slots)
//   TAPS         feedback set as a mask, bit t-1 per tap t (default disc: 32'h204)
//   SHIFT        track 2 phase shift D; must be 2^(N-1) + N - 1, which puts head 2 on
//                the last bit of W(p) (the only geometry this reader decodes)
//   FILTER       glitch filter length in clocks, 0 (off)..65535
//   ROM_FILE     conversion table from `prenc rom --bits N --taps ... --format hex`
//   COUNT_WIDTH  incremental count width, 2..64
//   ERROR_WIDTH  error counter widths, 1..32
//   RUN_LONG     agreeing slots for a single-track verification, 2N..2^N
//
// Ports
//   head1, head2, sync_a, sync_b   raw asynchronous inputs (datasheet levels)
//   resolution     0: `position` is pos_abs (N bits); 1: pos_hyb (N+2 bits)
//   clear_errors   zero the error counters
//   pos_abs        absolute slot p
//   pos_hyb        hybrid position 4p + q
//   pos_valid      pos_abs and pos_hyb are a verified absolute position
//   mode           0 acquiring, 1 normal, 2 reduced (track 1 only),
//                  3 reduced (track 2 only), 4 incremental
//   position       pos_abs or pos_hyb as `resolution` selects, zero-extended
//   incremental    signed multi-turn count of quadrature steps since reset
//   direction      1: the last step was CW
//   track1_valid   pos_valid, and track 1's own last N readings (N consecutive slots)
//                  are the code word of pos_abs: track 1 alone reads this position
//   track2_valid   the same for track 2
//   track1_pos, track2_pos   the position each track reads, valid with its flag
//   track1_errors, track2_errors   readings that disagreed with the prediction
//   sync_errors    illegal quadrature transitions

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_core #(
  parameter integer N           = 10,
  parameter [31:0]  TAPS        = 32'h0000_0204,
  parameter integer SHIFT       = (1 << (N - 1)) + N - 1,
  parameter integer FILTER      = 2,
  parameter         ROM_FILE    = "prenc_rom_n10.hex",
  parameter integer COUNT_WIDTH = 32,
  parameter integer ERROR_WIDTH = 16,
  parameter integer RUN_LONG    = (4 * N < (1 << N)) ? 4 * N : (1 << N)
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   head1,
  input  wire                   head2,
  input  wire                   sync_a,
  input  wire                   sync_b,
  input  wire                   resolution,
  input  wire                   clear_errors,
  output wire [N-1:0]           pos_abs,
  output wire [N+1:0]           pos_hyb,
  output wire                   pos_valid,
  output wire [2:0]             mode,
  output wire [N+1:0]           position,
  output wire [COUNT_WIDTH-1:0] incremental,
  output wire                   direction,
  output wire [N-1:0]           track1_pos,
  output wire                   track1_valid,
  output wire [N-1:0]           track2_pos,
  output wire                   track2_valid,
  output wire [ERROR_WIDTH-1:0] track1_errors,
  output wire [ERROR_WIDTH-1:0] track2_errors,
  output wire [ERROR_WIDTH-1:0] sync_errors
);

  generate
    if (N >= 2 && N <= 24 && SHIFT != (1 << (N - 1)) + N - 1) begin : g_bad_shift
      initial $display("ERROR: %m: parameter SHIFT = %0d must be 2^(N-1)+N-1 = %0d for N = %0d",
                       SHIFT, (1 << (N - 1)) + N - 1, N);
      prenc_core_parameter_SHIFT_must_be_2_pow_N_minus_1_plus_N_minus_1 u_stop ();
    end
  endgenerate

  // Datapath
  wire [1:0]             quarter;
  wire                   step;
  wire                   step_cw;
  wire                   illegal;
  wire                   strobe;
  wire [N-1:0]           word;
  wire                   word_full;
  wire                   check_now;
  wire                   mismatch1_now;
  wire                   mismatch2_now;
  wire                   flush;

  wire                   strobe_cw;
  wire [$clog2(N+1)-1:0] word_count;

  // Unused datapath outputs, named for waveforms.
  wire                   strobe_moved;
  wire                   strobe_head1;
  wire                   strobe_head2;
  wire [N-1:0]           word_known;
  wire                   predict1;
  wire                   predict2;
  wire                   check_d;
  wire                   expect1_d;
  wire                   expect2_d;
  wire                   mismatch1_d;
  wire                   mismatch2_d;

  prenc_datapath #(
    .N           (N),
    .TAPS        (TAPS),
    .FILTER      (FILTER),
    .COUNT_WIDTH (COUNT_WIDTH),
    .ERROR_WIDTH (ERROR_WIDTH)
  ) u_datapath (
    .clk           (clk),
    .rst           (rst),
    .head1         (head1),
    .head2         (head2),
    .sync_a        (sync_a),
    .sync_b        (sync_b),
    .clear_errors  (clear_errors),
    .flush         (flush),
    .quarter       (quarter),
    .step          (step),
    .step_cw       (step_cw),
    .illegal       (illegal),
    .illegal_count (sync_errors),
    .step_count    (incremental),
    .strobe        (strobe),
    .strobe_cw     (strobe_cw),
    .strobe_moved  (strobe_moved),
    .strobe_head1  (strobe_head1),
    .strobe_head2  (strobe_head2),
    .word          (word),
    .word_known    (word_known),
    .word_count    (word_count),
    .word_full     (word_full),
    .predict1      (predict1),
    .predict2      (predict2),
    .check_now     (check_now),
    .mismatch1_now (mismatch1_now),
    .mismatch2_now (mismatch2_now),
    .check         (check_d),
    .expect1       (expect1_d),
    .expect2       (expect2_d),
    .mismatch1     (mismatch1_d),
    .mismatch2     (mismatch2_d)
  );

  // Converter
  wire         conv_valid;
  wire [N-1:0] conv_pos;

  prenc_converter #(
    .N        (N),
    .ROM_FILE (ROM_FILE)
  ) u_converter (
    .clk        (clk),
    .rst        (rst),
    .word_valid (word_full),
    .word       (word),
    .pos_valid  (conv_valid),
    .pos        (conv_pos)
  );

  // Position
  wire [N-1:0] slot;
  wire         hyp_ready;

  prenc_position #(
    .N (N)
  ) u_position (
    .clk        (clk),
    .rst        (rst),
    .quarter    (quarter),
    .step       (step),
    .step_cw    (step_cw),
    .strobe     (strobe),
    .word_full  (word_full),
    .conv_valid (conv_valid),
    .conv_pos   (conv_pos),
    .slot       (slot),
    .hyp_ready  (hyp_ready),
    .pos_abs    (pos_abs),
    .pos_hyb    (pos_hyb)
  );

  // Track monitors
  wire run1_n_next;
  wire run1_2n_next;
  wire run1_long_next;
  wire run1_n;
  wire run2_n_next;
  wire run2_2n_next;
  wire run2_long_next;
  wire run2_n;
  wire restart    = ~word_full | illegal;
  wire word_empty = (word_count == {($clog2(N+1)){1'b0}});

  prenc_track_monitor #(
    .N           (N),
    .RUN_LONG    (RUN_LONG),
    .ERROR_WIDTH (ERROR_WIDTH)
  ) u_track1 (
    .clk           (clk),
    .rst           (rst),
    .clear         (restart),
    .fill          (strobe & ~word_full & ~strobe_cw),
    .word_empty    (word_empty),
    .check         (check_now),
    .mismatch      (mismatch1_now),
    .slot          (slot),
    .clear_errors  (clear_errors),
    .run_n_next    (run1_n_next),
    .run_2n_next   (run1_2n_next),
    .run_long_next (run1_long_next),
    .run_n         (run1_n),
    .errors        (track1_errors)
  );

  prenc_track_monitor #(
    .N           (N),
    .RUN_LONG    (RUN_LONG),
    .ERROR_WIDTH (ERROR_WIDTH)
  ) u_track2 (
    .clk           (clk),
    .rst           (rst),
    .clear         (restart),
    .fill          (strobe & ~word_full & strobe_cw),
    .word_empty    (word_empty),
    .check         (check_now),
    .mismatch      (mismatch2_now),
    .slot          (slot),
    .clear_errors  (clear_errors),
    .run_n_next    (run2_n_next),
    .run_2n_next   (run2_2n_next),
    .run_long_next (run2_long_next),
    .run_n         (run2_n),
    .errors        (track2_errors)
  );

  // Modes
  wire [N-1:0] error_slot;  // for waveforms

  prenc_mode_fsm #(
    .N (N)
  ) u_mode_fsm (
    .clk            (clk),
    .rst            (rst),
    .illegal        (illegal),
    .check          (check_now),
    .mismatch1      (mismatch1_now),
    .mismatch2      (mismatch2_now),
    .slot           (slot),
    .word_full      (word_full),
    .run1_n_next    (run1_n_next),
    .run2_n_next    (run2_n_next),
    .run1_2n_next   (run1_2n_next),
    .run2_2n_next   (run2_2n_next),
    .run1_long_next (run1_long_next),
    .run2_long_next (run2_long_next),
    .hyp_ready      (hyp_ready),
    .mode           (mode),
    .pos_valid      (pos_valid),
    .flush          (flush),
    .error_slot     (error_slot)
  );

  // Datapath outputs the core does not use, kept for waveforms (Verilator's
  // unused-signal pattern).
  wire unused_ok = &{1'b0, strobe_moved, strobe_head1, strobe_head2, word_known, predict1,
                     predict2, check_d, expect1_d, expect2_d, mismatch1_d, mismatch2_d,
                     error_slot};

  assign position     = resolution ? pos_hyb : {2'b00, pos_abs};
  assign direction    = step_cw;
  assign track1_pos   = pos_abs;
  assign track2_pos   = pos_abs;
  assign track1_valid = pos_valid & run1_n;
  assign track2_valid = pos_valid & run2_n;

endmodule

`resetall
