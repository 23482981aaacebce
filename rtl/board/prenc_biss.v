// SPDX-License-Identifier: Apache-2.0
// prenc_biss: BiSS-C slave, point to point, single-cycle sensor data (no register
// communication: CDS is always 0 and CDM is not read).
//
// The master drives the clock MA (idle high); the slave drives SLO (idle high). Bits
// change on the rising edges of MA, a few clocks late (the synchronizer); the master
// measures that delay at the start bit and samples each bit that late:
//
//   MA   ‾‾‾\_/‾\_/‾\_/‾\_/‾\_/‾\_/ ... ‾\_/‾\_/ ... ‾\_/‾\_/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾
//   SLO  ‾‾‾‾‾‾‾‾‾\___/‾‾‾\___X MSB X ... X nE X nW X CRC5 .. CRC0 X___ timeout __/‾‾
//           ^ latch  Ack  Start CDS  data                 (inverted)
//
// - The first falling edge of MA (idle) latches the frame: DATA_BITS of data
//   (multi-turn then single-turn, MSB first), nE (0: error, the position must not be
//   used) and nW (0: warning).
// - Rising edges of MA, counted from the first: 2 Ack (SLO low), 3 Start (high),
//   4 CDS (low), then the data bits, nE, nW, then the CRC-6 (x^6 + x + 1, start value
//   0, over the data bits, nE and nW) inverted, MSB first. Any rising edge after the
//   last CRC bit puts SLO low.
// - Timeout: when MA has had no edge for TIMEOUT clocks, SLO goes high and the slave
//   is idle, whether the frame ended, was cut short or MA stopped high or low (the
//   master may hold MA low for CDM = 1). A new frame needs that timeout first.
// - MA passes a two-flop synchronizer: SLO follows a rising edge of MA by 3 to 4
//   clocks. Each half period of MA must be at least 2 clocks (CLK_HZ >= 4 x the MA
//   frequency, 5 x for a margin); the master compensates the delay (BiSS line delay
//   compensation), which may exceed a bit time.
//
// Latency: the frame's data are latched on the clock the synchronized MA first falls, 2
// to 3 clocks after the pin; SLO follows each rising edge of MA by 3 to 4 clocks (the
// master compensates it).
//
// Parameters
//   DATA_BITS  multi-turn + single-turn bits, 1..64
//   TIMEOUT    clocks without an MA edge that end a frame, 2..16777215 (must be longer
//              than a half period of the slowest MA)
//
// Ports
//   clk, rst          one clock; synchronous active-high reset
//   data              multi-turn and single-turn bits, latched at the frame's start
//   error_n, warn_n   nE and nW, latched with them
//   ma                the master's clock (asynchronous)
//   slo               the slave's data line
//   busy              a frame is in progress (latch to the end of its timeout)
//   latch             one clock: the frame's data were latched on this clock
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_biss #(
  parameter integer DATA_BITS = 24,
  parameter integer TIMEOUT   = 480
) (
  input  wire                 clk,
  input  wire                 rst,
  input  wire [DATA_BITS-1:0] data,
  input  wire                 error_n,
  input  wire                 warn_n,
  input  wire                 ma,
  output wire                 slo,
  output wire                 busy,
  output wire                 latch
);

  generate
    if (DATA_BITS < 1 || DATA_BITS > 64) begin : g_bad_data_bits
      initial $display("ERROR: %m: parameter DATA_BITS = %0d is out of range 1..64", DATA_BITS);
      prenc_biss_parameter_DATA_BITS_out_of_range_1_to_64 u_stop ();
    end
    if (TIMEOUT < 2 || TIMEOUT > 16777215) begin : g_bad_timeout
      initial $display("ERROR: %m: parameter TIMEOUT = %0d is out of range 2..16777215", TIMEOUT);
      prenc_biss_parameter_TIMEOUT_out_of_range_2_to_16777215 u_stop ();
    end
  endgenerate

  localparam integer BITS = DATA_BITS + 2;  // data, nE, nW: what the CRC covers
  localparam [31:0]  TO32 = TIMEOUT - 1;
  localparam [23:0]  TO   = TO32[23:0];
  // Rising edge numbers (the first is 1): Ack 2, Start 3, CDS 4, data 5 .. 4 + BITS,
  // CRC 5 + BITS .. 10 + BITS.
  localparam [7:0]   ACK      = 8'd2;
  localparam [7:0]   START    = 8'd3;
  localparam [7:0]   CDS      = 8'd4;
  localparam [31:0]  LAST_D32 = 4 + BITS;
  localparam [31:0]  LAST_C32 = 10 + BITS;
  localparam [7:0]   LAST_D   = LAST_D32[7:0];
  localparam [7:0]   LAST_C   = LAST_C32[7:0];

  reg            ma_q1;
  reg            ma_q2;
  reg            ma_q3;
  reg            active;
  reg [BITS-1:0] shift;
  reg [5:0]      crc;
  reg [7:0]      rises;
  reg            slo_reg;
  reg [23:0]     timer;
  reg            latch_reg;

  wire fall = ma_q3 & ~ma_q2;
  wire rise = ~ma_q3 & ma_q2;
  wire [7:0] rise_no = rises + 8'd1;  // this rising edge's number
  // What it sends, decided from the edges counted before it (rises = rise_no - 1), so
  // that no adder stands before the comparisons; at 8'hFF (saturated) it sends nothing
  // new (rise_no would wrap to 0).
  localparam [7:0] RISES_MAX = 8'hFF;   // the count saturates
  wire at_ack   = (rises == ACK - 8'd1);
  wire at_start = (rises == START - 8'd1);
  wire at_cds   = (rises == CDS - 8'd1);
  wire in_data  = (rises >= CDS) && (rises < LAST_D);
  wire in_crc   = (rises >= LAST_D) && (rises < LAST_C);
  wire past_crc = (rises >= LAST_C) && (rises != RISES_MAX);
  // CRC-6, x^6 + x + 1, one bit MSB first.
  wire       feedback = crc[5] ^ shift[BITS-1];
  wire [5:0] crc_step = {crc[4:0], 1'b0} ^ {4'b0000, feedback, feedback};

  always @(posedge clk) begin
    ma_q1     <= ma;
    ma_q2     <= ma_q1;
    ma_q3     <= ma_q2;
    latch_reg <= 1'b0;
    if (!active) begin
      slo_reg <= 1'b1;
      if (fall) begin
        active    <= 1'b1;
        latch_reg <= 1'b1;
        shift     <= {data, error_n, warn_n};
        crc       <= 6'd0;
        rises     <= 8'd0;
        timer     <= TO;
      end
    end else begin
      if (rise) begin
        if (rises != RISES_MAX) begin
          rises <= rise_no;
        end
        if (at_ack || at_cds) begin
          slo_reg <= 1'b0;
        end else if (at_start) begin
          slo_reg <= 1'b1;
        end else if (in_data) begin
          slo_reg <= shift[BITS-1];
          shift   <= shift << 1;
          crc     <= crc_step;
        end else if (in_crc) begin
          slo_reg <= ~crc[5];
          crc     <= {crc[4:0], 1'b0};
        end else if (past_crc) begin
          slo_reg <= 1'b0;
        end
      end
      if (rise || fall) begin
        timer <= TO;
      end else if (timer != 24'd0) begin
        timer <= timer - 24'd1;
      end else begin
        active  <= 1'b0;
        slo_reg <= 1'b1;
      end
    end
    if (rst) begin
      ma_q1     <= 1'b1;
      ma_q2     <= 1'b1;
      ma_q3     <= 1'b1;
      active    <= 1'b0;
      slo_reg   <= 1'b1;
      latch_reg <= 1'b0;
    end
  end

  assign slo   = slo_reg;
  assign busy  = active;
  assign latch = latch_reg;

`ifdef FORMAL
  // Properties (formal/prenc_biss.sby), on the registers after each clock.
  reg            f_past_valid = 1'b0;
  reg            f_rst_prev;
  reg            f_active_prev;
  reg [BITS-1:0] f_frame;   // data, nE, nW latched at the frame's first falling edge
  reg [5:0]      f_crc;     // their CRC-6, computed here bit by bit from the frame
  reg [5:0]      f_crc_sent;  // the CRC of the bits sent so far
  reg [23:0]     f_still;   // clocks since MA last moved (saturating)
  integer        f_i;
  always @(*) begin
    f_crc      = 6'd0;
    f_crc_sent = 6'd0;
    for (f_i = BITS - 1; f_i >= 0; f_i = f_i - 1) begin
      f_crc = {f_crc[4:0], 1'b0} ^ ((f_crc[5] ^ f_frame[f_i]) ? 6'b000011 : 6'b000000);
      if (BITS - f_i <= rises - CDS) f_crc_sent = f_crc;
    end
  end
  always @(posedge clk) begin
    f_past_valid  <= 1'b1;
    f_rst_prev    <= rst;
    f_active_prev <= active;
    if (!active && fall) f_frame <= {data, error_n, warn_n};
    f_still <= (rise || fall) ? 24'd0 : (f_still == 24'hFFFFFF) ? f_still : f_still + 24'd1;
    if (rst) f_still <= 24'd0;
  end
  // MA as sampled at the last three clock edges: the synchronizer and the edges the
  // slave acts on are these samples; the first falling edge starts a frame.
  reg [2:0] f_raw = 3'b111;
  reg [1:0] f_raw_ok = 2'd0;  // clocks since the start, up to 3: the history is known
  reg       f_start;
  always @(posedge clk) begin
    f_raw   <= {f_raw[1:0], ma};
    f_start <= !active && f_raw[2] && !f_raw[1] && f_raw_ok == 2'd3 && !rst;
    if (f_raw_ok != 2'd3) f_raw_ok <= f_raw_ok + 2'd1;
    if (rst) f_raw <= 3'b111;  // reset puts the synchronizer at the idle level
  end
  initial assume (rst);
  always @(*) begin
    if (f_past_valid && !f_rst_prev && f_raw_ok == 2'd3) begin
      assert (ma_q1 == f_raw[0] && ma_q2 == f_raw[1] && ma_q3 == f_raw[2]);
      assert (rise == (!f_raw[2] && f_raw[1]) && fall == (f_raw[2] && !f_raw[1]));
    end
    if (f_past_valid && !f_rst_prev) begin
      assert (latch == f_start);
      if (f_start) assert (active && rises == 8'd0);
    end
    if (f_past_valid && !f_rst_prev) begin
      if (!active) assert (slo);
      // After rising edge k of a frame: 1 high, 2 Ack low, 3 Start high, 4 CDS low,
      // then the frame MSB first, then the CRC inverted, then low.
      if (active && rises == 8'd1) assert (slo);
      if (active && rises == ACK) assert (!slo);
      if (active && rises == START) assert (slo);
      if (active && rises == CDS) assert (!slo);
      if (active && rises > CDS && rises <= LAST_D) assert (slo == f_frame[LAST_D - rises]);
      if (active && rises > LAST_D && rises <= LAST_C) assert (slo == ~f_crc[LAST_C - rises]);
      if (active && rises > LAST_C) assert (!slo);
      // The latched frame holds for the whole frame: the shift register is its rest,
      // and the CRC register the CRC of what has been sent.
      if (active && rises <= CDS) assert (shift == f_frame && crc == 6'd0);
      if (active && rises > CDS && rises <= LAST_D)
        assert (shift == (f_frame << (rises - CDS)) && crc == f_crc_sent);
      if (active && rises > LAST_D && rises <= LAST_C) assert (crc == (f_crc << (rises - LAST_D)));
      // The timeout: a frame ends exactly when MA has not moved for TIMEOUT clocks.
      if (f_active_prev && !active) assert (f_still == TIMEOUT);
      if (active) assert (timer == ((f_still >= TIMEOUT - 1) ? 24'd0 : TO - f_still));
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (f_active_prev && !active && rises > LAST_C);  // a whole frame, then idle
    end
  end
`endif

endmodule

`resetall
