// prenc_mode_fsm: the reader's operating modes, and the only source of pos_valid.
//
//   0 ACQUIRE      after reset: the word is formed from the heads, converted, then
//                  verified; pos_valid = 0
//   1 NORMAL       both tracks agree with the prediction; pos_valid = 1
//   2 REDUCED_1    track 2 disagreed, running on track 1; pos_valid = 1
//   3 REDUCED_2    track 1 disagreed, running on track 2; pos_valid = 1
//   4 INCREMENTAL  after a fault: counting from the quadrature only while the word
//                  is formed and verified again; pos_valid = 0
//
// Everything happens at a check (a strobe with a full word, both heads against the
// prediction) or at an illegal quadrature transition:
// - Verifying (ACQUIRE, INCREMENTAL): a track that disagrees is marked bad until the
//   word is formed again. Both marked: the word is flushed and formed anew. The
//   position is verified when both tracks have agreed over 2N consecutive slots, or
//   one track over RUN_LONG (see prenc_track_monitor); the mode becomes NORMAL, or
//   REDUCED on that track if the other has not reached N.
// - NORMAL: one track disagrees -> REDUCED on the other, remembering the slot.
//   Both disagree -> INCREMENTAL, flush.
// - REDUCED on track g: track g disagrees -> INCREMENTAL, flush. The other track
//   disagrees again -> stays, remembering the new slot. The other track reads
//   right at the remembered slot -> it was a one-time error: NORMAL.
// - An illegal quadrature transition (the datapath flushes the word) -> pos_valid
//   drops: INCREMENTAL, or ACQUIRE if no position was ever verified.
// The position itself is counted by prenc_position; this machine only says whether
// a reading has verified it since the last fault and none has contradicted it.
//
// Parameters
//   N   slot count width, 2..24
//
// Ports
//   illegal               illegal quadrature transition on this clock
//   check, mismatch1/2    this clock's check (prenc_datapath *_now)
//   slot                  incremental slot count of the strobe
//   word_full             the word is full (registered in the shift register)
//   run1_n_next ...       prenc_track_monitor outputs of tracks 1 and 2
//   hyp_ready             the position of the word is loaded (prenc_position)
//   mode                  as above
//   pos_valid             mode is NORMAL or REDUCED
//   flush                 form the word again from the heads (combinational)
//   error_slot            incremental slot of the last one-track disagreement

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_mode_fsm #(
  parameter integer N = 10
) (
  input  wire         clk,
  input  wire         rst,
  input  wire         illegal,
  input  wire         check,
  input  wire         mismatch1,
  input  wire         mismatch2,
  input  wire [N-1:0] slot,
  input  wire         word_full,
  input  wire         run1_n_next,
  input  wire         run2_n_next,
  input  wire         run1_2n_next,
  input  wire         run2_2n_next,
  input  wire         run1_long_next,
  input  wire         run2_long_next,
  input  wire         hyp_ready,
  output wire [2:0]   mode,
  output wire         pos_valid,
  output wire         flush,
  output wire [N-1:0] error_slot
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_mode_fsm_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  localparam [2:0] ACQUIRE     = 3'd0;
  localparam [2:0] NORMAL      = 3'd1;
  localparam [2:0] REDUCED_1   = 3'd2;
  localparam [2:0] REDUCED_2   = 3'd3;
  localparam [2:0] INCREMENTAL = 3'd4;

  reg [2:0]   mode_reg;
  reg         bad1_reg;
  reg         bad2_reg;
  reg [N-1:0] error_slot_reg;

  wire valid = (mode_reg == NORMAL) | (mode_reg == REDUCED_1) | (mode_reg == REDUCED_2);

  reg [2:0]   mode_next;
  reg         bad1_next;
  reg         bad2_next;
  reg [N-1:0] error_slot_next;
  reg         flush_next;

  // A one-track disagreement on this check: which track failed.
  wire only1 = check & mismatch1 & ~mismatch2;
  wire only2 = check & mismatch2 & ~mismatch1;
  wire both  = check & mismatch1 & mismatch2;

  always @* begin
    mode_next       = mode_reg;
    bad1_next       = bad1_reg & word_full;
    bad2_next       = bad2_reg & word_full;
    error_slot_next = (only1 | only2) ? slot : error_slot_reg;
    flush_next      = 1'b0;
    if (check && !valid) begin
      bad1_next = bad1_next | mismatch1;
      bad2_next = bad2_next | mismatch2;
      if (bad1_next && bad2_next) begin
        flush_next = 1'b1;
      end else if (hyp_ready && ((run1_2n_next && run2_2n_next) || run1_long_next)) begin
        mode_next = run2_n_next ? NORMAL : REDUCED_1;
      end else if (hyp_ready && run2_long_next) begin
        mode_next = run1_n_next ? NORMAL : REDUCED_2;
      end
    end else if (check) begin
      if (both) begin
        mode_next  = INCREMENTAL;
        flush_next = 1'b1;
      end else if (mode_reg == NORMAL) begin
        if (only1) begin
          mode_next = REDUCED_2;
        end else if (only2) begin
          mode_next = REDUCED_1;
        end
      end else if (mode_reg == REDUCED_1) begin
        if (only1) begin
          mode_next  = INCREMENTAL;
          flush_next = 1'b1;
        end else if (!mismatch2 && slot == error_slot_reg) begin
          mode_next = NORMAL;
        end
      end else begin  // REDUCED_2
        if (only2) begin
          mode_next  = INCREMENTAL;
          flush_next = 1'b1;
        end else if (!mismatch1 && slot == error_slot_reg) begin
          mode_next = NORMAL;
        end
      end
    end
    if (illegal) begin
      mode_next  = (mode_next == ACQUIRE) ? ACQUIRE : INCREMENTAL;
      flush_next = 1'b0;  // the datapath flushes on illegal by itself
    end
  end

  always @(posedge clk) begin
    mode_reg       <= mode_next;
    bad1_reg       <= bad1_next;
    bad2_reg       <= bad2_next;
    error_slot_reg <= error_slot_next;
    if (rst) begin
      mode_reg       <= ACQUIRE;
      bad1_reg       <= 1'b0;
      bad2_reg       <= 1'b0;
      error_slot_reg <= {N{1'b0}};
    end
  end

  assign mode       = mode_reg;
  assign pos_valid  = valid;
  assign flush      = flush_next & ~rst;
  assign error_slot = error_slot_reg;

endmodule

`resetall
