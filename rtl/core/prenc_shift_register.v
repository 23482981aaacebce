// SPDX-License-Identifier: Apache-2.0
// prenc_shift_register: the main code word, formed from whichever head leads.
//
// At slot p the word is W(p) = s(p) .. s(p+N-1), s(p) in the MSB. Head 1 reads
// s(p), the MSB; head 2 reads s(p+N-1), the LSB. On a strobe that reached a new slot:
//   CW  (p -> p+1): shift left,  head 2's s(p+N) enters as the LSB;
//   CCW (p -> p-1): shift right, head 1's s(p-1) enters as the MSB.
// On a strobe at the same slot (a reversal), nothing shifts; the leading head's bit
// fills that end of the word if it is not known yet.
//
// `known` marks the bits read since reset or the last flush (a break in continuity);
// it shifts with the word, and `count` is how many of them there are (the number of
// ones in `known`), so `full` (count = N) is when the word can be converted.
//
// Parameters
//   N   code word length, 2..24
//
// Ports (outputs registered)
//   flush                    forget every bit (continuity lost); wins over a strobe
//   strobe, strobe_cw, strobe_moved, strobe_head1, strobe_head2   from prenc_sampler
//   word, known, count, full

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_shift_register #(
  parameter integer N = 10
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   flush,
  input  wire                   strobe,
  input  wire                   strobe_cw,
  input  wire                   strobe_moved,
  input  wire                   strobe_head1,
  input  wire                   strobe_head2,
  output wire [N-1:0]           word,
  output wire [N-1:0]           known,
  output wire [$clog2(N+1)-1:0] count,
  output wire                   full
);

  localparam integer CW = $clog2(N + 1);
  localparam [31:0]  N32 = N;

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_shift_register_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  reg [N-1:0]  word_reg;
  reg [N-1:0]  known_reg;
  reg [CW-1:0] count_reg;

  always @(posedge clk) begin
    if (strobe) begin
      if (strobe_moved && strobe_cw) begin
        word_reg  <= {word_reg[N-2:0], strobe_head2};
        known_reg <= {known_reg[N-2:0], 1'b1};
        count_reg <= count_reg + 1'b1 - {{(CW-1){1'b0}}, known_reg[N-1]};
      end else if (strobe_moved) begin
        word_reg  <= {strobe_head1, word_reg[N-1:1]};
        known_reg <= {1'b1, known_reg[N-1:1]};
        count_reg <= count_reg + 1'b1 - {{(CW-1){1'b0}}, known_reg[0]};
      end else if (strobe_cw && !known_reg[0]) begin
        word_reg[0]  <= strobe_head2;
        known_reg[0] <= 1'b1;
        count_reg    <= count_reg + 1'b1;
      end else if (!strobe_cw && !known_reg[N-1]) begin
        word_reg[N-1]  <= strobe_head1;
        known_reg[N-1] <= 1'b1;
        count_reg      <= count_reg + 1'b1;
      end
    end
    if (rst || flush) begin
      known_reg <= {N{1'b0}};
      count_reg <= {CW{1'b0}};
    end
  end

  assign word  = word_reg;
  assign known = known_reg;
  assign count = count_reg;
  assign full  = (count_reg == N32[CW-1:0]);

`ifdef FORMAL
  // Properties (formal/prenc_shift_register.sby), on the registers after each clock.
  reg          f_past_valid = 1'b0;
  reg          f_rst_prev;
  reg          f_shift_cw;      // last clock: a CW shift
  reg          f_shift_ccw;     // last clock: a CCW shift
  reg [N-1:0]  f_word_before;   // the word and known bits before last clock
  reg [N-1:0]  f_known_before;
  reg          f_h1;
  reg          f_h2;
  reg          f_armed_cw;      // the word's last change was a CW shift from f_w0
  reg          f_armed_ccw;     // ... a CCW shift from f_w0
  reg [N-1:0]  f_w0;
  reg          f_restore;       // last clock shifted back over the bit that left
  reg [N-1:0]  f_restore_word;
  reg          f_fill_cw;       // last clock: a strobe that did not move filled bit 0
  reg          f_fill_ccw;      // ... bit N-1
  integer      f_i;
  reg [CW-1:0] f_ones;
  always @(*) begin
    f_ones = {CW{1'b0}};
    for (f_i = 0; f_i < N; f_i = f_i + 1) f_ones = f_ones + {{(CW-1){1'b0}}, known_reg[f_i]};
  end
  wire f_cw  = strobe & strobe_moved & strobe_cw;
  wire f_ccw = strobe & strobe_moved & !strobe_cw;
  always @(posedge clk) begin
    f_past_valid   <= 1'b1;
    f_rst_prev     <= rst | flush;
    f_shift_cw     <= f_cw;
    f_shift_ccw    <= f_ccw;
    f_word_before  <= word_reg;
    f_known_before <= known_reg;
    f_h1           <= strobe_head1;
    f_h2           <= strobe_head2;
    f_restore      <= (f_ccw & f_armed_cw & (strobe_head1 == f_w0[N-1])) |
                      (f_cw & f_armed_ccw & (strobe_head2 == f_w0[0]));
    f_restore_word <= f_w0;
    f_fill_cw      <= strobe & !strobe_moved & strobe_cw & !known_reg[0];
    f_fill_ccw     <= strobe & !strobe_moved & !strobe_cw & !known_reg[N-1];
    f_armed_cw     <= f_cw;
    f_armed_ccw    <= f_ccw;
    if (f_cw || f_ccw) f_w0 <= word_reg;
    if (rst || flush) begin
      f_restore   <= 1'b0;
      f_armed_cw  <= 1'b0;
      f_armed_ccw <= 1'b0;
    end
  end
  initial assume (rst);
  always @(*) begin
    if (f_past_valid) begin
      // count is the number of known bits; full is all of them.
      assert (count_reg == f_ones);
      assert (full == (known_reg == {N{1'b1}}));
    end
    if (f_past_valid && !f_rst_prev) begin
      // CW: the word moves up one and the leading head 2 enters at the LSB; CCW the
      // mirror, with head 1 at the MSB.
      if (f_shift_cw) assert (word_reg == {f_word_before[N-2:0], f_h2} &&
                              known_reg == {f_known_before[N-2:0], 1'b1});
      if (f_shift_ccw) assert (word_reg == {f_h1, f_word_before[N-1:1]} &&
                               known_reg == {1'b1, f_known_before[N-1:1]});
      // A shift back undoes a shift forward, when the head reads the bit that left.
      if (f_restore) assert (word_reg == f_restore_word);
      // Without a shift no known bit changes or is forgotten; a strobe that did not
      // move fills only the end bit its leading head reads, and only when unknown.
      if (!f_shift_cw && !f_shift_ccw) begin
        assert (((word_reg ^ f_word_before) & f_known_before) == {N{1'b0}});
        assert (known_reg == (f_known_before | ({{(N - 1){1'b0}}, f_fill_ccw} << (N - 1)) |
                              {{(N - 1){1'b0}}, f_fill_cw}));
        if (f_fill_cw) assert (word_reg[0] == f_h2);
        if (f_fill_ccw) assert (word_reg[N-1] == f_h1);
      end
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (full);
      cover (f_restore);
    end
  end
`endif

endmodule

`resetall
