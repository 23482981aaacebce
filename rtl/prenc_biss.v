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
        if (rises != 8'hFF) begin
          rises <= rise_no;
        end
        if (rise_no == ACK || rise_no == CDS) begin
          slo_reg <= 1'b0;
        end else if (rise_no == START) begin
          slo_reg <= 1'b1;
        end else if (rise_no > CDS && rise_no <= LAST_D) begin
          slo_reg <= shift[BITS-1];
          shift   <= shift << 1;
          crc     <= crc_step;
        end else if (rise_no > LAST_D && rise_no <= LAST_C) begin
          slo_reg <= ~crc[5];
          crc     <= {crc[4:0], 1'b0};
        end else if (rise_no > LAST_C) begin
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

endmodule

`resetall
