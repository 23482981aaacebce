// SPDX-License-Identifier: Apache-2.0
// prenc_uart_rx: UART receiver, 8 data bits, no parity, 1 stop bit (8N1), LSB first.
//
// The line goes through a two-flop synchronizer. A falling edge starts a byte; the
// start bit is checked again half a bit later (a shorter pulse is noise and is
// ignored), then every bit is sampled once, in its middle, CLKS_PER_BIT clocks
// apart. A low stop bit is a framing error: the byte is dropped, `frame_error`
// pulses, and the receiver waits for the line to go high (a break) before it
// looks for the next start bit.
//
// Latency: the line passes a two-flop synchronizer; `valid` pulses in the middle of the
// stop bit, 9.5 bit times after the start bit's falling edge, plus the synchronizer's 2
// clocks.
//
// Parameters
//   CLKS_PER_BIT   clocks per bit, round(clock / baud), >= 4
//
// Ports
//   clk, rst      one clock; synchronous active-high reset
//   rx            the asynchronous serial line (idle high)
//   data, valid   a received byte, `valid` high for one clock
//   frame_error   one clock: a byte with a low stop bit was dropped
//   busy          a byte is being received (from the start bit to the stop bit)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_uart_rx #(
  parameter integer CLKS_PER_BIT = 16
) (
  input  wire       clk,
  input  wire       rst,
  input  wire       rx,
  output wire [7:0] data,
  output wire       valid,
  output wire       frame_error,
  output wire       busy
);

  generate
    if (CLKS_PER_BIT < 4 || CLKS_PER_BIT > 65535) begin : g_bad_clks_per_bit
      initial $display("ERROR: %m: parameter CLKS_PER_BIT = %0d is out of range 4..65535",
                       CLKS_PER_BIT);
      prenc_uart_rx_parameter_CLKS_PER_BIT_out_of_range_4_to_65535 u_stop ();
    end
  endgenerate

  localparam [31:0] FULL_32 = CLKS_PER_BIT - 1;
  localparam [31:0] HALF_32 = CLKS_PER_BIT / 2 - 1;
  localparam integer TW     = $clog2(CLKS_PER_BIT);  // the bit timer, as wide as a bit needs
  localparam [TW-1:0] FULL  = FULL_32[TW-1:0];
  localparam [TW-1:0] HALF  = HALF_32[TW-1:0];

  localparam [1:0] IDLE  = 2'd0;
  localparam [1:0] START = 2'd1;
  localparam [1:0] BITS  = 2'd2;
  localparam [1:0] BREAK = 2'd3;

  reg        rx_q1;
  reg        rx_q2;
  reg [1:0]  state;
  reg [TW-1:0] timer;
  reg [3:0]  bit_index;  // 0..7 data, 8 stop
  reg [7:0]  shift;
  reg        valid_reg;
  reg        error_reg;

  always @(posedge clk) begin
    rx_q1     <= rx;
    rx_q2     <= rx_q1;
    valid_reg <= 1'b0;
    error_reg <= 1'b0;
    case (state)
      IDLE: begin
        if (!rx_q2) begin
          state <= START;
          timer <= HALF;
        end
      end
      START: begin
        if (timer != {TW{1'b0}}) begin
          timer <= timer - 1'b1;
        end else if (rx_q2) begin
          state <= IDLE;  // too short for a start bit
        end else begin
          state     <= BITS;
          timer     <= FULL;
          bit_index <= 4'd0;
        end
      end
      BITS: begin
        if (timer != {TW{1'b0}}) begin
          timer <= timer - 1'b1;
        end else if (bit_index != 4'd8) begin
          shift     <= {rx_q2, shift[7:1]};
          bit_index <= bit_index + 4'd1;
          timer     <= FULL;
        end else if (rx_q2) begin
          state     <= IDLE;
          valid_reg <= 1'b1;
        end else begin
          state     <= BREAK;
          error_reg <= 1'b1;
        end
      end
      default: begin  // BREAK: wait for the idle level
        if (rx_q2) begin
          state <= IDLE;
        end
      end
    endcase
    if (rst) begin
      rx_q1     <= 1'b1;
      rx_q2     <= 1'b1;
      state     <= IDLE;
      valid_reg <= 1'b0;
      error_reg <= 1'b0;
    end
  end

  assign data        = shift;
  assign valid       = valid_reg;
  assign frame_error = error_reg;
  assign busy        = (state == START) | (state == BITS);

`ifdef FORMAL
  // Properties (formal/prenc_uart_rx.sby).
  // 1. It cannot lock up: after any input, once the line has been high for a byte
  //    time (and the synchronizer), the receiver is idle.
  // 2. It accepts a good byte then: a byte sent after that idle time, at the exact
  //    bit time, is received with its value, once; the same byte with a low stop bit
  //    is a framing error, once, and no byte.
  // 3. After a framing error it waits while the line stays low (a break): no byte, no
  //    error, not busy, until the line is high again.
  localparam integer F_IDLE = 2 + 10 * CLKS_PER_BIT;   // clocks of high line
  localparam integer F_END  = 10 * CLKS_PER_BIT + 4;   // a byte's frame and the latency
  reg        f_past_valid = 1'b0;
  reg        f_rst_prev;
  reg [7:0]  f_high;                      // clocks the line has been high (saturating)
  (* anyconst *) reg [7:0] f_byte;        // the byte a sender sends
  (* anyseq *)   reg       f_go;          // ... when it chooses, after an idle line
  (* anyconst *) reg       f_bad_stop;    // ... with a low stop bit
  reg        f_sending;
  reg [7:0]  f_t;                         // clocks since the start bit began
  reg [1:0]  f_got;                       // bytes received during the frame
  reg        f_wrong;                     // a byte other than f_byte
  reg [1:0]  f_errs;                      // framing errors during the frame
  wire [3:0] f_bit = f_t / CLKS_PER_BIT;  // 0 start, 1..8 data LSB first, 9 stop
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_rst_prev   <= rst;
    f_high       <= !rx ? 8'd0 : (f_high == 8'hFF) ? f_high : f_high + 8'd1;
    if (!f_sending && f_go && f_high >= F_IDLE && !rst) begin
      f_sending <= 1'b1;
      f_t       <= 8'd0;
      f_got     <= 2'd0;
      f_wrong   <= 1'b0;
      f_errs    <= 2'd0;
    end else if (f_sending && f_t != 8'hFF) begin
      f_t <= f_t + 8'd1;
      if (valid) begin
        f_got   <= f_got + 2'd1;
        f_wrong <= f_wrong | (data != f_byte);
      end
      if (frame_error && f_errs != 2'd3) f_errs <= f_errs + 2'd1;
    end
    if (rst) f_sending <= 1'b0;
  end
  // rx as sampled three clock edges ago: what rx_q2 held on the last clock.
  reg [2:0] f_rx = 3'b111;
  always @(posedge clk) f_rx <= {f_rx[1:0], rx};
  // The data bits of a byte follow a start bit: BITS entered from START (its low
  // middle sampled), START entered from IDLE (a falling line), neither left since.
  reg  [1:0] f_state_prev;
  reg        f_started_prev;
  reg        f_framed_prev;
  wire       f_started = (state == START) &&
                         (f_state_prev == IDLE || (f_state_prev == START && f_started_prev));
  wire       f_framed  = (state == BITS) &&
                         ((f_state_prev == START && f_started_prev) ||
                          (f_state_prev == BITS && f_framed_prev));
  always @(posedge clk) begin
    f_state_prev   <= rst ? IDLE : state;
    f_started_prev <= !rst && f_started;
    f_framed_prev  <= !rst && f_framed;
  end
  always @(*) begin
    // A byte is accepted only on a high stop bit sample; a low one is a framing error.
    if (f_past_valid && !f_rst_prev && valid) assert (f_rx[2]);
    if (f_past_valid && !f_rst_prev && frame_error) assert (!f_rx[2]);
    // Either ends a byte that began with a start bit.
    if (f_past_valid && !f_rst_prev && (valid || frame_error)) assert (f_framed_prev);
  end
  initial assume (rst);
  initial assume (!f_sending);
  always @(*) begin
    if (!f_past_valid) assume (!f_sending);
    if (f_past_valid) assume (!rst);
    // The sender's waveform: start bit, eight data bits LSB first, stop bit, idle.
    if (f_sending && f_t < 8'hF0) begin
      if (f_bit == 4'd0) assume (!rx);
      else if (f_bit <= 4'd8) assume (rx == f_byte[f_bit - 4'd1]);
      else if (f_bit == 4'd9) assume (rx == !f_bad_stop);
      else assume (rx);
    end
    if (f_past_valid && !f_rst_prev) begin
      if (f_high >= F_IDLE) assert (state == IDLE && !busy);
      // Busy from the start bit's middle to the stop bit's sample.
      if (f_sending && f_t >= 8'd3 + CLKS_PER_BIT / 2 && f_t <= 8'd2 + 9 * CLKS_PER_BIT) begin
        assert (busy);
      end
      if (state == BITS) assert (bit_index <= 4'd8 && timer <= FULL);
      if (state == START) assert (timer <= HALF);
      if (f_high >= 8'd2) assert (rx_q2);
      if (f_sending && f_t == F_END) begin
        if (f_bad_stop) assert (f_got == 2'd0 && f_errs == 2'd1);
        else assert (f_got == 2'd1 && !f_wrong && f_errs == 2'd0);
      end
    end
  end
  // 3: f_break = a framing error, and the line low (as the receiver saw it) since.
  reg f_break = 1'b0;
  always @(posedge clk) f_break <= !rst && (frame_error || f_break) && !rx_q2;
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      if (frame_error) assert (state == BREAK);
      if (f_break) assert (state == BREAK && !valid && !frame_error);
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) cover (f_sending && f_t == F_END);
    if (f_past_valid && !rst) cover (f_break && rx_q2);  // a break that ends
  end
`endif

endmodule

`resetall
