// SPDX-License-Identifier: Apache-2.0
// prenc_predictor: dual-head LFSR predictor, which tells which track erred.
//
// At each strobe it predicts what both heads must read, from the current word
// W(p) (before the shift register takes the strobe), the direction and the disc's
// next-bit laws, and flags each head that disagrees:
//   CW to p+1:   head 2 must read s(p+N) = forward law of W(p)   (leading head)
//                head 1 must read s(p+1) = bit N-2 of W(p)       (trailing head)
//   CCW to p-1:  head 1 must read s(p-1) = inverse law of W(p)   (leading head)
//                head 2 must read s(p+N-2) = bit 1 of W(p)       (trailing head)
//   same slot:   head 1 must read s(p) = MSB, head 2 s(p+N-1) = LSB
// Laws (datasheet), with the de Bruijn correction in brackets:
//   forward  s(p+N) = XOR_{t in T} s(p+N-t) ^ [s(p+1..p+N-1) all zero]
//   inverse  s(p-1) = s(p+N-1) ^ XOR_{t in T, t<N} s(p+N-1-t) ^ [s(p..p+N-2) all zero]
// Each head is checked against a bit that came, through the word, mostly from the
// other track or from the law, so a mismatch on one head locates the error to
// that head's track. Checks are made only when the word is full.
//
// Parameters
//   N      code word length, 2..24
//   TAPS   feedback set T as a mask: bit t-1 set for each tap t (bit N-1 always);
//          the default disc T = {10, 3} is 32'h204. `prenc taps` prints it.
//          Primitivity is checked where the ROM is made (`prenc rom`, `prenc taps`).
//
// Ports
//   strobe, strobe_cw, strobe_moved, strobe_head1, strobe_head2   from prenc_sampler
//   word, full               from prenc_shift_register
//   predict1, predict2       what each head must read at this strobe (combinational,
//                            valid with strobe and full); once the word is full the
//                            datapath shifts these in instead of the raw readings
// Registered, one clock after the strobe:
//   check                    a check was made
//   expect1, expect2         the predicted head readings
//   mismatch1, mismatch2     head 1 / head 2 read otherwise (only with check)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_predictor #(
  parameter integer N    = 10,
  parameter [31:0]  TAPS = 32'h0000_0204
) (
  input  wire         clk,
  input  wire         rst,
  input  wire         strobe,
  input  wire         strobe_cw,
  input  wire         strobe_moved,
  input  wire         strobe_head1,
  input  wire         strobe_head2,
  input  wire [N-1:0] word,
  input  wire         full,
  output wire         predict1,
  output wire         predict2,
  output wire         check,
  output wire         expect1,
  output wire         expect2,
  output wire         mismatch1,
  output wire         mismatch2
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_predictor_parameter_N_out_of_range_2_to_24 u_stop ();
    end else if (TAPS[N-1] != 1'b1 || (TAPS >> N) != 32'd0 || TAPS[N-2:0] == 0) begin : g_bad_taps
      initial $display("ERROR: %m: parameter TAPS = 'h%0h is not a feedback set for N = %0d",
                       TAPS, N);
      prenc_predictor_parameter_TAPS_not_a_feedback_set_for_N u_stop ();
    end
  endgenerate

  wire forward_bit;
  wire inverse_bit;

  prenc_disc_law #(
    .N    (N),
    .TAPS (TAPS)
  ) u_law (
    .word        (word),
    .forward_bit (forward_bit),
    .inverse_bit (inverse_bit)
  );

  reg expect1_next;
  reg expect2_next;

  always @* begin
    if (!strobe_moved) begin
      expect1_next = word[N-1];
      expect2_next = word[0];
    end else if (strobe_cw) begin
      expect1_next = word[N-2];
      expect2_next = forward_bit;
    end else begin
      expect1_next = inverse_bit;
      expect2_next = word[1];
    end
  end

  reg check_reg;
  reg expect1_reg;
  reg expect2_reg;
  reg mismatch1_reg;
  reg mismatch2_reg;

  always @(posedge clk) begin
    check_reg     <= strobe & full;
    mismatch1_reg <= strobe & full & (strobe_head1 != expect1_next);
    mismatch2_reg <= strobe & full & (strobe_head2 != expect2_next);
    if (strobe) begin
      expect1_reg <= expect1_next;
      expect2_reg <= expect2_next;
    end
    if (rst) begin
      check_reg     <= 1'b0;
      mismatch1_reg <= 1'b0;
      mismatch2_reg <= 1'b0;
    end
  end

  assign predict1  = expect1_next;
  assign predict2  = expect2_next;
  assign check     = check_reg;
  assign expect1   = expect1_reg;
  assign expect2   = expect2_reg;
  assign mismatch1 = mismatch1_reg;
  assign mismatch2 = mismatch2_reg;

`ifdef FORMAL
  // Properties (formal/prenc_predictor.sby), against the disc as the datasheet builds
  // it (formal/prenc_disc_reference.vh), not as the law computes it.
  `include "prenc_disc_reference.vh"
  // The bits after and before the word on the disc, found by searching the disc.
  reg     f_next;
  reg     f_prev;
  reg     f_found;
  integer f_p;
  always @(*) begin
    f_next  = 1'b0;
    f_prev  = 1'b0;
    f_found = 1'b0;
    for (f_p = 0; f_p < F_L; f_p = f_p + 1) begin
      if (f_window(f_p) == word) begin
        f_found = 1'b1;
        f_next  = F_S[(f_p + N) % F_L];
        f_prev  = F_S[(f_p + F_L - 1) % F_L];
      end
    end
  end
  reg f_past_valid = 1'b0;
  reg f_rst_prev;
  reg f_check_next;
  reg f_mis1_next;
  reg f_mis2_next;
  reg f_strobe_prev;
  reg f_pred1_prev;
  reg f_pred2_prev;
  reg f_exp1_prev;
  reg f_exp2_prev;
  always @(posedge clk) begin
    f_strobe_prev <= strobe;
    f_pred1_prev  <= predict1;
    f_pred2_prev  <= predict2;
    f_exp1_prev   <= expect1;
    f_exp2_prev   <= expect2;
  end
  always @(*) begin
    // expect1/2 hold the last strobe's predictions until the next strobe.
    if (f_past_valid && f_strobe_prev) assert (expect1 == f_pred1_prev && expect2 == f_pred2_prev);
    if (f_past_valid && !f_strobe_prev) assert (expect1 == f_exp1_prev && expect2 == f_exp2_prev);
  end
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_rst_prev   <= rst;
    f_check_next <= strobe & full;
    f_mis1_next  <= strobe & full & (strobe_head1 != predict1);
    f_mis2_next  <= strobe & full & (strobe_head2 != predict2);
  end
  initial assume (rst);
  always @(*) begin
    assert (f_found);  // every word is on the disc once (de Bruijn)
    // The leading head's next bit is the disc law on the word; the trailing head's
    // is already in the word; a reversal re-reads both ends.
    if (strobe_moved && strobe_cw) assert (predict2 == f_next && predict1 == word[N-2]);
    if (strobe_moved && !strobe_cw) assert (predict1 == f_prev && predict2 == word[1]);
    if (!strobe_moved) assert (predict1 == word[N-1] && predict2 == word[0]);
    // Each check of a full word flags exactly the heads that disagree.
    if (f_past_valid && !f_rst_prev) begin
      assert (check == f_check_next && mismatch1 == f_mis1_next && mismatch2 == f_mis2_next);
    end
  end
`endif

endmodule

`resetall
