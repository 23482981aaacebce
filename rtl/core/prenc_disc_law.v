// SPDX-License-Identifier: Apache-2.0
// prenc_disc_law: the disc's next-bit laws applied to a code word (combinational).
//
// word = W(p), the MSB is s(p) (datasheet). With the de Bruijn term in brackets:
//   forward  s(p+N) = XOR_{t in T} s(p+N-t) ^ [s(p+1..p+N-1) all zero]
//   inverse  s(p-1) = s(p+N-1) ^ XOR_{t in T, t<N} s(p+N-1-t) ^ [s(p..p+N-2) all zero]
// The one place these laws are written in the RTL: prenc_track_word uses it.
// Model: prenc.debruijn forward_bit / inverse_bit.
//
// Latency: none, combinational.
//
// Parameters
//   N      code word length, 2..24
//   TAPS   feedback set T as a mask: bit t-1 set for each tap t (default disc: 32'h204)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_disc_law #(
  parameter integer N    = 10,
  parameter [31:0]  TAPS = 32'h0000_0204
) (
  input  wire [N-1:0] word,
  output wire         forward_bit,
  output wire         inverse_bit
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_disc_law_parameter_N_out_of_range_2_to_24 u_stop ();
    end else if (TAPS[N-1] != 1'b1 || (TAPS >> N) != 32'd0 || TAPS[N-2:0] == 0) begin : g_bad_taps
      initial $display("ERROR: %m: parameter TAPS = 'h%0h is not a feedback set for N = %0d",
                       TAPS, N);
      prenc_disc_law_parameter_TAPS_not_a_feedback_set_for_N u_stop ();
    end
  endgenerate

  wire [N-1:0] taps = TAPS[N-1:0];

  assign forward_bit = (^(word & taps)) ^ (word[N-2:0] == {(N - 1){1'b0}});
  assign inverse_bit = word[0] ^ (^(word[N-1:1] & taps[N-2:0])) ^
                       (word[N-1:1] == {(N - 1){1'b0}});

endmodule

`resetall
