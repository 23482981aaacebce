// SPDX-License-Identifier: Apache-2.0
// prenc_correlator: position of a whole-window reading by summed cross-correlation.
//
// For a line or area sensor that sees all of a reading at once: M tracks of N bits,
// P samples per bit, each sample a B-bit intensity. The reading is latched on `start`;
// the decoder then tests K*P candidates (k, f), one per clock: the window starts f/P
// of a bit after bit k, so sample q of bit i shows bit i + (q + f >= P) of the
// candidate's (N+1)-bit window on each track, read from the ROM (address k).
//   soft (hard = 0): score = sum over samples of +x~ where that bit is 1, -x~ where 0,
//                    x~ = 2x - (2^B - 1) (the sample centred on mid-scale);
//   hard (hard = 1): bit (j, i) reads 1 when the sum of its x~ is > 0; score = the
//                    number of the M*N bits equal to the candidate's first N bits,
//                    so the nearest window wins and (D-1)/2 misread bits are corrected.
// Pass 1 finds the best score (first candidate on a tie); pass 2 the best score of the
// candidates whose k is at least 2 away (cyclically) from the best's. ambiguous is
// best - second < threshold. The Python model is prenc.nd.correlator (same integers).
//
// Latency: `done` is high on the 2*K*P + 4th rising edge after the one that takes `start`
// (K*P candidates per pass, 2 passes, 4 pipeline clocks); busy is
// high from that clock until done. A start while busy is ignored.
//
// Parameters (checked; an illegal value stops elaboration with the name of the problem)
//   M 1..4, N 2..16, P 1..8, B 1..12, K 4..4096
//   ROM_FILE  $readmemh, K words of M*(N+1) bits: bit j*(N+1)+i = bit i of track j's
//             window at position k (`prenc nd rom`). A missing or short file stops
//             simulation at time 0.
//
// Ports: samples: sample (j, i, q) is bits [((j*N + i)*P + q)*B +: B].

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_correlator #(
  parameter integer M        = 1,
  parameter integer N        = 10,
  parameter integer P        = 4,
  parameter integer B        = 8,
  parameter integer K        = 170,
  parameter         ROM_FILE = "prenc_correlator.hex",
  // derived; do not override
  parameter integer KW       = (K > 1) ? $clog2(K) : 1,
  parameter integer PW       = (P > 1) ? $clog2(P) : 1,
  parameter integer SW       = $clog2(M * N * P * ((1 << B) - 1) + 1) + 2
) (
  input  wire                 clk,
  input  wire                 rst,
  input  wire                 start,
  input  wire                 hard,
  input  wire [SW-1:0]        threshold,
  input  wire [M*N*P*B-1:0]   samples,
  output wire                 busy,
  output reg                  done,
  output reg  [KW-1:0]        position,
  output reg  [PW-1:0]        fraction,
  output reg  signed [SW-1:0] score,
  output reg  signed [SW-1:0] second,
  output reg                  ambiguous
);

  localparam integer W  = M * (N + 1);
  localparam integer NS = M * N * P;
  localparam integer XW = B + 1;           // centred sample, signed

  generate
    if (M < 1 || M > 4) begin : g_bad_m
      initial $display("ERROR: %m: parameter M = %0d is out of range 1..4", M);
      prenc_correlator_parameter_M_out_of_range_1_to_4 u_stop ();
    end
    if (N < 2 || N > 16) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..16", N);
      prenc_correlator_parameter_N_out_of_range_2_to_16 u_stop ();
    end
    if (P < 1 || P > 8) begin : g_bad_p
      initial $display("ERROR: %m: parameter P = %0d is out of range 1..8", P);
      prenc_correlator_parameter_P_out_of_range_1_to_8 u_stop ();
    end
    if (B < 1 || B > 12) begin : g_bad_b
      initial $display("ERROR: %m: parameter B = %0d is out of range 1..12", B);
      prenc_correlator_parameter_B_out_of_range_1_to_12 u_stop ();
    end
    if (K < 4 || K > 4096) begin : g_bad_k
      initial $display("ERROR: %m: parameter K = %0d is out of range 4..4096", K);
      prenc_correlator_parameter_K_out_of_range_4_to_4096 u_stop ();
    end
  endgenerate

  // ---- the window ROM (registered read: block RAM) -------------------------------
  reg [W-1:0] rom [0:K-1];
  initial $readmemh(ROM_FILE, rom);

  localparam [31:0]   K_32   = K;
  localparam [31:0]   KL_32  = K - 1;
  localparam [31:0]   PL_32  = P - 1;
  localparam [KW-1:0] K_LAST = KL_32[KW-1:0];
  localparam [PW-1:0] P_LAST = PL_32[PW-1:0];
  localparam [KW:0]   K_WIDE = K_32[KW:0];
  localparam [XW-1:0] MID    = {1'b0, {B{1'b1}}};

  // ---- the reading, centred: x~ = 2x - (2^B - 1), and the hard bit decisions ------
  wire [NS*XW-1:0] x_in;
  wire [M*N-1:0]   hard_in;

  genvar gj, gi, gq;
  generate
    for (gj = 0; gj < M; gj = gj + 1) begin : g_track_in
      for (gi = 0; gi < N; gi = gi + 1) begin : g_bit_in
        reg signed [SW-1:0] bit_sum;
        integer             qq;
        for (gq = 0; gq < P; gq = gq + 1) begin : g_sample_in
          localparam integer S = (gj*N + gi)*P + gq;
          assign x_in[S*XW +: XW] = {samples[S*B +: B], 1'b0} - MID;
        end
        always @(*) begin
          bit_sum = {SW{1'b0}};
          for (qq = 0; qq < P; qq = qq + 1) begin
            bit_sum = bit_sum + {{(SW-XW){x_in[((gj*N + gi)*P + qq)*XW + XW-1]}},
                                 x_in[((gj*N + gi)*P + qq)*XW +: XW]};
          end
        end
        assign hard_in[gj*N + gi] = (bit_sum > 0);
      end
    end
  endgenerate

  reg [NS*XW-1:0] xs;
  reg [M*N-1:0]   hard_bits;
  reg             hard_r;
  reg [SW-1:0]    threshold_r;

  // ---- candidate counter: pass 1 then pass 2 ------------------------------------
  reg          running;
  reg          pass;        // 0: best, 1: second
  reg [KW-1:0] k_cnt;
  reg [PW-1:0] f_cnt;
  wire         last_cand = (k_cnt == K_LAST) && (f_cnt == P_LAST);

  // pipeline: stage 1 = ROM word of (k1, f1); stage 2 = score of (k2, f2)
  reg          v1, v2, p1, p2, l1, l2;
  reg [KW-1:0] k1, k2;
  reg [PW-1:0] f1, f2;
  reg [W-1:0]  rom_q;
  reg signed [SW-1:0] score2;

  always @(posedge clk) begin
    rom_q <= rom[k_cnt];
  end

  // ---- the score of the candidate in stage 1 ------------------------------------
  wire [NS*SW-1:0]  soft_term;
  wire [M*N-1:0]    agree;
  generate
    for (gj = 0; gj < M; gj = gj + 1) begin : g_track
      for (gi = 0; gi < N; gi = gi + 1) begin : g_bit
        assign agree[gj*N + gi] = (hard_bits[gj*N + gi] == rom_q[gj*(N+1) + gi]);
        for (gq = 0; gq < P; gq = gq + 1) begin : g_sample
          localparam integer  S    = (gj*N + gi)*P + gq;
          localparam [31:0]   E_32 = P - gq;      // sample q shows the next bit when f >= P - q
          localparam [PW:0]   EDGE = E_32[PW:0];
          wire                nb   = ({1'b0, f1} >= EDGE);
          wire                bv   = nb ? rom_q[gj*(N+1) + gi + 1] : rom_q[gj*(N+1) + gi];
          wire signed [SW-1:0] xe  = {{(SW-XW){xs[S*XW + XW-1]}}, xs[S*XW +: XW]};
          assign soft_term[S*SW +: SW] = bv ? xe : -xe;
        end
      end
    end
  endgenerate

  reg signed [SW-1:0] score_c;
  integer             t;
  always @(*) begin
    score_c = {SW{1'b0}};
    if (hard_r) begin
      for (t = 0; t < M*N; t = t + 1) begin
        score_c = score_c + {{(SW-1){1'b0}}, agree[t]};
      end
    end else begin
      for (t = 0; t < NS; t = t + 1) begin
        score_c = score_c + soft_term[t*SW +: SW];
      end
    end
  end

  // ---- compare ------------------------------------------------------------------
  reg [KW-1:0]        best_k;
  reg [PW-1:0]        best_f;
  reg signed [SW-1:0] best_s, second_s;
  reg                 have_best, have_second;
  wire [KW:0] kd_up   = (k2 >= best_k) ? ({1'b0, k2} - {1'b0, best_k})
                                       : ({1'b0, best_k} - {1'b0, k2});
  wire [KW:0] kd_down = K_WIDE - kd_up;
  wire        far     = (kd_up >= 2) && (kd_down >= 2);
  wire        take_second = far && (!have_second || score2 > second_s);
  wire signed [SW-1:0] second_final = take_second ? score2 : (have_second ? second_s : best_s);
  wire [SW-1:0] gap   = best_s - second_final;

  assign busy = running | v1 | v2;

  always @(posedge clk) begin
    done <= 1'b0;
    if (start && !busy) begin
      xs          <= x_in;
      hard_bits   <= hard_in;
      hard_r      <= hard;
      threshold_r <= threshold;
    end
    // issue
    v1 <= running;
    p1 <= pass;
    l1 <= running && last_cand;
    k1 <= k_cnt;
    f1 <= f_cnt;
    if (start && !busy) begin
      running     <= 1'b1;
      pass        <= 1'b0;
      k_cnt       <= {KW{1'b0}};
      f_cnt       <= {PW{1'b0}};
      have_best   <= 1'b0;
      have_second <= 1'b0;
    end else if (running) begin
      if (f_cnt == P_LAST) begin
        f_cnt <= {PW{1'b0}};
        k_cnt <= (k_cnt == K_LAST) ? {KW{1'b0}} : k_cnt + 1'b1;
      end else begin
        f_cnt <= f_cnt + 1'b1;
      end
      if (last_cand) begin
        running <= 1'b0;    // pass 2 starts when the last candidate of pass 1 is compared
      end
    end
    // score
    v2     <= v1;
    p2     <= p1;
    l2     <= l1;
    k2     <= k1;
    f2     <= f1;
    score2 <= score_c;
    // compare
    if (v2 && !p2) begin
      if (!have_best || score2 > best_s) begin
        best_s <= score2;
        best_k <= k2;
        best_f <= f2;
      end
      have_best <= 1'b1;
      if (l2) begin
        running <= 1'b1;
        pass    <= 1'b1;
        k_cnt   <= {KW{1'b0}};
        f_cnt   <= {PW{1'b0}};
      end
    end
    if (v2 && p2) begin
      if (take_second) begin
        second_s    <= score2;
        have_second <= 1'b1;
      end
      if (l2) begin
        done      <= 1'b1;
        position  <= best_k;
        fraction  <= best_f;
        score     <= best_s;
        second    <= second_final;
        ambiguous <= (gap < threshold_r);
      end
    end
    if (rst) begin
      running <= 1'b0;
      v1      <= 1'b0;
      v2      <= 1'b0;
      done    <= 1'b0;
    end
  end

`ifndef SYNTHESIS
  // A missing or short ROM file must not become an all-X or all-zero ROM.
  prenc_rom_check #(
    .NAME  ("ROM_FILE"),
    .FILE  (ROM_FILE),
    .DEPTH (K),
    .WIDTH (W)
  ) u_rom_check ();
`endif

endmodule

`resetall
