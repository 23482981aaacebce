// SPDX-License-Identifier: Apache-2.0
// prenc_ssi: SSI output, the synchronous serial interface of absolute encoders.
//
// The controller drives the clock (ssi_clk, idle high); the encoder drives data
// (ssi_data, idle high):
//
//   ssi_clk  ‾‾‾‾\__/‾‾\__/‾‾\__ ... __/‾‾\__/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾
//   ssi_data ‾‾‾‾‾‾‾‾| MSB | ... |  LSB | ERR |(WRN)|___ monoflop ___/‾‾‾‾‾
//                ^ first falling edge: the position and its error bit are latched
//
// - The first falling edge latches `position` (Gray-coded when `gray` is high) and
//   the error bit (1 when `valid` is low: the position must not be used).
// - Each rising edge puts the next bit on ssi_data, MSB first, the error bit after the
//   position (ERROR_BIT = 1), and with WARN_BIT = 1 the warning bit last (1: the
//   warning, prenc_health's); the controller samples on the falling edges, so a frame
//   of B bits takes B + 1 clock pulses.
// - After the last bit, and on any further clock pulse, ssi_data is low; when the
//   clock has stayed high for the monoflop time (MONOFLOP clocks), ssi_data goes
//   high again and the next falling edge latches a new position. A frame that
//   stops early also ends at the monoflop time.
// - ssi_clk passes a two-flop synchronizer: data follows a rising edge of ssi_clk
//   by at most 4 clocks, so a half period of ssi_clk must be longer than that
//   (at 24 MHz, up to about 2 MHz SSI clock).
//
// Latency: the position is latched on the clock the synchronized ssi_clk first falls (2
// to 3 clocks after the pin); ssi_data follows each rising edge by at most 4 clocks.
//
// Parameters
//   WIDTH      position bits, 1..32
//   ERROR_BIT  1: append the error bit; 0: position bits only
//   WARN_BIT   1: append the warning bit after the error bit (needs ERROR_BIT = 1); 0: not
//   MONOFLOP   monoflop time in clocks, >= 2 (typically 20 us)
//
// Ports
//   clk, rst          one clock; synchronous active-high reset
//   position, valid   what is latched
//   warn              the warning, latched with them (used with WARN_BIT = 1)
//   gray              1: Gray code, 0: binary (sampled at the latch)
//   ssi_clk           the controller's clock (asynchronous)
//   ssi_data          the data line
//   busy              a frame is in progress (latch to end of monoflop)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_ssi #(
  parameter integer WIDTH     = 12,
  parameter integer ERROR_BIT = 1,
  parameter integer WARN_BIT  = 0,
  parameter integer MONOFLOP  = 480
) (
  input  wire             clk,
  input  wire             rst,
  input  wire [WIDTH-1:0] position,
  input  wire             valid,
  input  wire             warn,
  input  wire             gray,
  input  wire             ssi_clk,
  output wire             ssi_data,
  output wire             busy
);

  generate
    if (WIDTH < 1 || WIDTH > 32) begin : g_bad_width
      initial $display("ERROR: %m: parameter WIDTH = %0d is out of range 1..32", WIDTH);
      prenc_ssi_parameter_WIDTH_out_of_range_1_to_32 u_stop ();
    end
    if (ERROR_BIT < 0 || ERROR_BIT > 1) begin : g_bad_error_bit
      initial $display("ERROR: %m: parameter ERROR_BIT = %0d must be 0 or 1", ERROR_BIT);
      prenc_ssi_parameter_ERROR_BIT_must_be_0_or_1 u_stop ();
    end
    if (WARN_BIT < 0 || WARN_BIT > 1 || (WARN_BIT == 1 && ERROR_BIT != 1)) begin : g_bad_warn_bit
      initial $display("ERROR: %m: parameter WARN_BIT = %0d must be 0, or 1 with ERROR_BIT = 1",
                       WARN_BIT);
      prenc_ssi_parameter_WARN_BIT_must_be_0_or_1_with_ERROR_BIT u_stop ();
    end
    if (MONOFLOP < 2 || MONOFLOP > 16777215) begin : g_bad_monoflop
      initial $display("ERROR: %m: parameter MONOFLOP = %0d is out of range 2..16777215", MONOFLOP);
      prenc_ssi_parameter_MONOFLOP_out_of_range_2_to_16777215 u_stop ();
    end
  endgenerate

  // The shift register always has room for the error bit.
  localparam integer BITS = WIDTH + 1 + ((WARN_BIT == 1) ? 1 : 0);
  localparam [31:0] MONO_32 = MONOFLOP - 1;
  localparam [23:0] MONO    = MONO_32[23:0];

  reg              clk_q1;
  reg              clk_q2;
  reg              clk_q3;
  reg              active;
  reg [BITS-1:0]   shift;
  reg              data_reg;
  reg [23:0]       timer;

  wire fall = clk_q3 & ~clk_q2;
  wire rise = ~clk_q3 & clk_q2;

  wire [WIDTH-1:0] coded = gray ? (position ^ (position >> 1)) : position;
  wire [BITS-1:0]  frame;
  generate
    if (WARN_BIT == 1) begin : g_frame_warn
      assign frame = {coded, ~valid, warn};
    end else if (ERROR_BIT == 1) begin : g_frame_error
      assign frame = {coded, ~valid};
    end else begin : g_frame_position
      assign frame = {1'b0, coded};
      wire unused_frame = &{1'b0, valid, warn};
    end
    if (WARN_BIT == 0 && ERROR_BIT == 1) begin : g_no_warn
      wire unused_warn = &{1'b0, warn};
    end
  endgenerate

  always @(posedge clk) begin
    clk_q1 <= ssi_clk;
    clk_q2 <= clk_q1;
    clk_q3 <= clk_q2;
    if (!active) begin
      data_reg <= 1'b1;
      if (fall) begin
        active <= 1'b1;
        shift  <= (ERROR_BIT == 1) ? frame : (frame << 1);
        timer  <= MONO;
      end
    end else begin
      if (rise) begin
        data_reg <= shift[BITS-1];
        shift    <= shift << 1;
      end
      if (rise || fall || !clk_q2) begin
        timer <= MONO;
      end else if (timer != 24'd0) begin
        timer <= timer - 24'd1;
      end else begin
        active   <= 1'b0;
        data_reg <= 1'b1;
      end
    end
    if (rst) begin
      clk_q1   <= 1'b1;
      clk_q2   <= 1'b1;
      clk_q3   <= 1'b1;
      active   <= 1'b0;
      data_reg <= 1'b1;
    end
  end

  assign ssi_data = data_reg;
  assign busy     = active;

`ifdef FORMAL
  // Properties (formal/prenc_ssi.sby), on the registers after each clock.
  reg             f_past_valid = 1'b0;
  reg             f_rst_prev;
  reg             f_active_prev;
  reg [BITS-1:0]  f_frame;     // the frame latched at the first falling edge
  reg [7:0]       f_rises;     // rising edges of the frame so far
  reg [23:0]      f_still;     // clocks since ssi_clk last moved or was low (saturating)
  always @(posedge clk) begin
    f_past_valid  <= 1'b1;
    f_rst_prev    <= rst;
    f_active_prev <= active;
    if (!active && fall) begin
      f_frame <= (ERROR_BIT == 1) ? f_code : (f_code << 1);
      f_rises <= 8'd0;
    end else if (active && rise && f_rises != 8'hFF) begin
      f_rises <= f_rises + 8'd1;
    end
    f_still <= (rise || fall || !clk_q2) ? 24'd0 :
               (f_still == 24'hFFFFFF) ? f_still : f_still + 24'd1;
    if (rst) f_still <= 24'd0;
  end
  // The frame as the datasheet of SSI says, written here: the position in Gray code
  // (p ^ p >> 1) or binary, MSB first, then the error bit (1 = not valid), then with
  // WARN_BIT the warning bit.
  reg [BITS-1:0] f_code;
  always @(*) begin
    if (WARN_BIT == 1) f_code = {gray ? (position ^ (position >> 1)) : position, ~valid, warn};
    else f_code = {gray ? (position ^ (position >> 1)) : position, ~valid};
    if (ERROR_BIT == 0) f_code = {1'b0, f_code[BITS-1:1]};
  end
  // ssi_clk as sampled at the last three clock edges (f_raw[0] the newest): the
  // synchronizer, and the edges the module acts on, are these samples.
  reg [2:0] f_raw = 3'b111;
  reg [1:0] f_raw_ok = 2'd0;  // clocks since the start, up to 3: the history is known
  always @(posedge clk) begin
    f_raw <= {f_raw[1:0], ssi_clk};
    if (f_raw_ok != 2'd3) f_raw_ok <= f_raw_ok + 2'd1;
    if (rst) f_raw <= 3'b111;  // reset puts the synchronizer at the idle level
  end
  initial assume (rst);
  // The first falling edge of ssi_clk starts a frame (the clock after the module saw it).
  reg f_start;
  always @(posedge clk) f_start <= !active && f_raw[2] && !f_raw[1] && f_raw_ok == 2'd3;
  always @(*) begin
    if (f_past_valid && !f_rst_prev && f_start) assert (active && shift == f_frame);
    if (f_past_valid && !f_rst_prev && f_raw_ok == 2'd3) begin
      assert (clk_q1 == f_raw[0] && clk_q2 == f_raw[1] && clk_q3 == f_raw[2]);
      assert (rise == (!f_raw[2] && f_raw[1]) && fall == (f_raw[2] && !f_raw[1]));
    end
    if (f_past_valid && !f_rst_prev) begin
      // Idle: data high.
      if (!active) assert (ssi_data);
      // The k-th rising edge of a frame puts frame bit k (MSB first) on the line;
      // after the last bit the line is low until the monoflop time.
      if (active && f_rises >= 1 && f_rises <= BITS - ((ERROR_BIT == 1) ? 0 : 1))
        assert (ssi_data == f_frame[BITS - f_rises]);
      if (active && f_rises > BITS - ((ERROR_BIT == 1) ? 0 : 1)) assert (!ssi_data);
      // The latched frame does not change during a frame: the shift register holds
      // exactly its remaining bits.
      if (active) assert (shift == (f_frame << f_rises));
      // The monoflop: a frame ends only when the clock has been high and still for
      // MONOFLOP clocks, and it does end then.
      if (f_active_prev && !active) assert (f_still == MONOFLOP);
      if (active) assert (timer == ((f_still >= MONOFLOP - 1) ? 24'd0 : MONO - f_still));
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (f_active_prev && !active && f_rises == BITS);  // a whole frame
    end
  end
`endif

endmodule

`resetall
