// SPDX-License-Identifier: Apache-2.0
// prenc_as5047: an SPI slave that answers as the ams AS5047P angle sensor does, so that
// drives written for that sensor (ODrive, SimpleFOC, moteus, VESC, Klipper) read the
// reader's angle unchanged (docs/interfaces/as5047.md).
//
// SPI mode 1 (SCLK idles low, the master samples MISO and the slave MOSI on SCLK's
// falling edges), 16-bit frames, MSB first, one frame per CSn low:
//
//   CSn   ‾‾\___________________________________________/‾‾‾‾‾‾
//   SCLK  ______/‾\_/‾\_/‾\_ ... _/‾\_/‾\___________________
//   MOSI      | PARC | R/W |  address 13..0          |          command frame
//   MISO  -z--| PARD |  EF |  data 13..0             |--z--     answer frame
//
// - A command (bit 15 even parity over bits 14:0, bit 14 1 = read, address 13:0) is
//   decoded when CSn rises; the register it names is answered in the next frame. Its
//   contents are taken when that frame's CSn falls: an angle is the one at that instant.
// - A write command is followed by a data frame (bit 15 parity, data 13:0); the data
//   frame's answer is the register's old contents, the next frame's its new contents.
//   0x0000 (a write to NOP) is a NOP, as drivers send it (SimpleFOC): no data follows.
// - Errors (ERRFL, cleared when its contents are answered): FRERR, a frame of other
//   than 16 clocks; PARERR, a frame with bad parity; INVCOMM, an address that does not
//   exist, or a write to a register that is read-only. A frame with an error does
//   nothing: the next frame answers the register that was answered before. The EF bit
//   of an answer is 1 while ERRFL is not 0. The first frame after reset answers
//   ANGLECOM (a driver that sends 0xFFFF gets the angle, or EF, from its first frame).
// - Registers (the datasheet's addresses; 8-bit ones in bits 7:0, the rest read 0):
//     0x0000 NOP        0
//     0x0001 ERRFL      2 PARERR, 1 INVCOMM, 0 FRERR
//     0x0003 PROG       read and written; no OTP: it has no effect
//     0x0016 ZPOSM      the zero's bits 13:6
//     0x0017 ZPOSL      5:0 the zero's bits 5:0; 7:6 read and written
//     0x0018 SETTINGS1  2 DIR (1: the angle counts down as the reader counts up); the
//                       other bits read and written (`settings1` for other blocks)
//     0x0019 SETTINGS2  7:5 ABIRES, 4:3 HYS, 2:0 UVWPP (`settings2` for other blocks)
//     0x3FFC DIAAGC     11 MAGL: the warning (prenc_health: the corrections grow, as a
//                       weakening magnet's field would), 10 MAGH 0, 9 COF: the position
//                       is not valid, 8 LF: the position has been valid since reset,
//                       7:0 AGC 0x80
//     0x3FFD MAG        0x1000, a constant: there is no field
//     0x3FFE ANGLEUNC   the angle, as ANGLECOM: the reader has no dynamic angle error
//     0x3FFF ANGLECOM   the angle: ((DIR ? -1 - angle : angle) - zero) mod 2^14 (with DIR
//                       the one's complement: the floor of the turned angle, as the
//                       angle itself is the floor of the fine position)
// - While `valid` is 0 an angle answer carries EF = 1 and the last valid angle (0
//   before the first): drives that check EF (ODrive, VESC, Klipper) drop it.
// - The pins pass two-flop synchronizers, so that nothing on them can disturb the
//   clock domain. The slave counts SCLK's falling edges: each puts the next bit on MISO
//   (combinationally, from the clock that sees the edge: 2 to 3 clocks after it) and
//   takes MOSI as the synchronizer saw it. A period of SCLK must be longer than 2
//   clocks plus the output delay and the master's setup time, and each half period
//   longer than a clock: up to 10 MHz at 30 MHz (docs/interfaces/as5047.md). MISO is
//   driven (miso_oe) while the synchronized CSn is low, from 2 to 3 clocks after CSn
//   falls (the AS5047P allows the master 350 ns there).
//
// Latency: an angle answer carries `angle` (and `valid`) of the clock before the one
// CSn's fall is first seen on (2 to 3 clocks after the pin); a zero or DIR written
// counts from the clock after.
//
// Parameters
//   ZERO       the zero after reset, 0..16383 (ZPOSM, ZPOSL's bits 5:0)
//   SETTINGS1  SETTINGS1 after reset, 0..255 (0x01, the AS5047P's)
//   SETTINGS2  SETTINGS2 after reset, 0..255 (0x00)
//
// Ports
//   clk, rst          one clock; synchronous active-high reset
//   angle, valid      the angle (2^-14 turn) and its validity, latency compensated
//   warning           prenc_health's warning, shown as DIAAGC's MAGL
//                     to the clock after they are given
//   csn, sclk, mosi   the master's (asynchronous)
//   miso, miso_oe     the answer, and 1 while it is driven (a tristate on the pin)
//   zero, settings1, settings2   the registers, for the blocks that follow them

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_as5047 #(
  parameter integer ZERO      = 0,
  parameter integer SETTINGS1 = 1,
  parameter integer SETTINGS2 = 0
) (
  input  wire        clk,
  input  wire        rst,
  input  wire [13:0] angle,
  input  wire        valid,
  input  wire        warning,
  input  wire        csn,
  input  wire        sclk,
  input  wire        mosi,
  output wire        miso,
  output wire        miso_oe,
  output wire [13:0] zero,
  output wire [7:0]  settings1,
  output wire [7:0]  settings2
);

  generate
    if (ZERO < 0 || ZERO > 16383) begin : g_bad_zero
      initial $display("ERROR: %m: parameter ZERO = %0d is out of range 0..16383", ZERO);
      prenc_as5047_parameter_ZERO_out_of_range_0_to_16383 u_stop ();
    end
    if (SETTINGS1 < 0 || SETTINGS1 > 255) begin : g_bad_settings1
      initial $display("ERROR: %m: parameter SETTINGS1 = %0d is out of range 0..255", SETTINGS1);
      prenc_as5047_parameter_SETTINGS1_out_of_range_0_to_255 u_stop ();
    end
    if (SETTINGS2 < 0 || SETTINGS2 > 255) begin : g_bad_settings2
      initial $display("ERROR: %m: parameter SETTINGS2 = %0d is out of range 0..255", SETTINGS2);
      prenc_as5047_parameter_SETTINGS2_out_of_range_0_to_255 u_stop ();
    end
  endgenerate

  // The datasheet's addresses.
  localparam [13:0] A_NOP       = 14'h0000;
  localparam [13:0] A_ERRFL     = 14'h0001;
  localparam [13:0] A_PROG      = 14'h0003;
  localparam [13:0] A_ZPOSM     = 14'h0016;
  localparam [13:0] A_ZPOSL     = 14'h0017;
  localparam [13:0] A_SETTINGS1 = 14'h0018;
  localparam [13:0] A_SETTINGS2 = 14'h0019;
  localparam [13:0] A_DIAAGC    = 14'h3FFC;
  localparam [13:0] A_MAG       = 14'h3FFD;
  localparam [13:0] A_ANGLEUNC  = 14'h3FFE;
  localparam [13:0] A_ANGLECOM  = 14'h3FFF;
  // The registers' numbers, as the slave keeps the address it answers.
  localparam [3:0] R_NOP       = 4'd0;
  localparam [3:0] R_ERRFL     = 4'd1;
  localparam [3:0] R_PROG      = 4'd2;
  localparam [3:0] R_ZPOSM     = 4'd3;
  localparam [3:0] R_ZPOSL     = 4'd4;
  localparam [3:0] R_SETTINGS1 = 4'd5;
  localparam [3:0] R_SETTINGS2 = 4'd6;
  localparam [3:0] R_DIAAGC    = 4'd7;
  localparam [3:0] R_MAG       = 4'd8;
  localparam [3:0] R_ANGLEUNC  = 4'd9;
  localparam [3:0] R_ANGLECOM  = 4'd10;
  localparam [3:0] R_NONE      = 4'd15;   // no such register
  // ERRFL's bits.
  localparam integer FRERR   = 0;
  localparam integer INVCOMM = 1;
  localparam integer PARERR  = 2;
  // What DIAAGC and MAG show.
  localparam [7:0]  AGC       = 8'h80;
  localparam [13:0] MAGNITUDE = 14'h1000;

  localparam [31:0] ZERO_32 = ZERO;
  localparam [31:0] S1_32   = SETTINGS1;
  localparam [31:0] S2_32   = SETTINGS2;

  // Synchronizers; an edge is seen between the second and the third flop.
  reg csn_q1, csn_q2, csn_q3;
  reg sclk_q1, sclk_q2, sclk_q3;
  reg mosi_q1, mosi_q2;
  always @(posedge clk) begin
    csn_q1  <= csn;
    csn_q2  <= csn_q1;
    csn_q3  <= csn_q2;
    sclk_q1 <= sclk;
    sclk_q2 <= sclk_q1;
    sclk_q3 <= sclk_q2;
    mosi_q1 <= mosi;
    mosi_q2 <= mosi_q1;
    if (rst) begin
      csn_q1  <= 1'b1;
      csn_q2  <= 1'b1;
      csn_q3  <= 1'b1;
      sclk_q1 <= 1'b0;
      sclk_q2 <= 1'b0;
      sclk_q3 <= 1'b0;
    end
  end

  wire selected   = ~csn_q2;
  wire frame_open = csn_q3 & ~csn_q2;
  wire frame_shut = ~csn_q3 & csn_q2;
  wire bit_edge   = selected & sclk_q3 & ~sclk_q2;   // SCLK fell while selected

  // The registers.
  reg  [2:0]  errfl;
  reg  [7:0]  prog;
  reg  [7:0]  zposm;
  reg  [7:0]  zposl;
  reg  [7:0]  set1;
  reg  [7:0]  set2;
  reg  [3:0]  answer;           // the register the next frame answers (R_*)
  reg         write_pending;    // the frame being received is a write's data
  reg         been_valid;       // LF
  reg  [13:0] held;             // the last valid angle

  // The angle turned by DIR and less the zero, registered: `angle` of the clock before.
  reg  [13:0] angle_now;
  reg         valid_now;
  wire        dir        = set1[2];
  wire [13:0] zero_now   = {zposm, zposl[5:0]};
  wire [13:0] directed   = dir ? ~angle : angle;   // -angle - 1: the floor of -(the angle)
  always @(posedge clk) begin
    angle_now <= directed - zero_now;
    valid_now <= rst ? 1'b0 : valid;
  end
  wire [13:0] angle_out  = valid_now ? angle_now : held;

  // The answer's data, taken when the frame opens.
  reg [13:0] data;
  always @* begin
    case (answer)
      R_ERRFL:     data = {11'd0, errfl};
      R_PROG:      data = {6'd0, prog};
      R_ZPOSM:     data = {6'd0, zposm};
      R_ZPOSL:     data = {6'd0, zposl};
      R_SETTINGS1: data = {6'd0, set1};
      R_SETTINGS2: data = {6'd0, set2};
      R_DIAAGC:    data = {2'd0, warning, 1'b0, ~valid_now, been_valid, AGC};
      R_MAG:       data = MAGNITUDE;
      R_ANGLEUNC:  data = angle_out;
      R_ANGLECOM:  data = angle_out;
      default:     data = 14'd0;   // NOP
    endcase
  end
  wire is_angle     = (answer == R_ANGLEUNC) | (answer == R_ANGLECOM);
  wire error_flag   = (errfl != 3'd0) | (is_angle & ~valid_now);
  wire [15:0] reply = {^{error_flag, data}, error_flag, data};

  // The frame: the answer shifts out, the command shifts in.
  reg  [15:0] tx;
  reg  [15:0] rx;
  reg  [4:0]  clocks;   // falling edges of SCLK, saturating at 31
  wire [15:0] rx_next     = bit_edge ? {rx[14:0], mosi_q2} : rx;
  wire [4:0]  clocks_next = (bit_edge && clocks != 5'd31) ? clocks + 5'd1 : clocks;

  // What the frame that ended says, decoded on the clock after CSn's rise was seen (its
  // last SCLK edge is in rx and clocks by then).
  reg         frame_done;
  wire        frame_error   = (clocks != 5'd16);
  wire        parity_error  = ^rx;
  wire        is_read       = rx[14];
  reg  [3:0]  named;        // the register the command names
  always @* begin
    case (rx[13:0])
      A_NOP:       named = R_NOP;
      A_ERRFL:     named = R_ERRFL;
      A_PROG:      named = R_PROG;
      A_ZPOSM:     named = R_ZPOSM;
      A_ZPOSL:     named = R_ZPOSL;
      A_SETTINGS1: named = R_SETTINGS1;
      A_SETTINGS2: named = R_SETTINGS2;
      A_DIAAGC:    named = R_DIAAGC;
      A_MAG:       named = R_MAG;
      A_ANGLEUNC:  named = R_ANGLEUNC;
      A_ANGLECOM:  named = R_ANGLECOM;
      default:     named = R_NONE;
    endcase
  end
  wire        is_nop        = (named == R_NOP);
  wire        writable      = (named >= R_PROG) & (named <= R_SETTINGS2);
  wire        bad_command   = ~write_pending & (is_read ? (named == R_NONE) : ~(writable | is_nop));
  wire        frame_good    = ~frame_error & ~parity_error;

  always @(posedge clk) begin
    rx     <= rx_next;
    clocks <= clocks_next;
    if (bit_edge) begin
      tx <= {tx[14:0], 1'b0};
    end
    if (valid_now) begin
      held       <= angle_now;
      been_valid <= 1'b1;
    end
    if (frame_open) begin
      tx     <= reply;
      rx     <= 16'd0;
      clocks <= 5'd0;
      if (answer == R_ERRFL) begin
        errfl <= 3'd0;
      end
    end
    frame_done <= frame_shut;
    if (frame_done) begin
      if (!frame_good || bad_command) begin
        errfl[FRERR]   <= errfl[FRERR] | frame_error;
        errfl[PARERR]  <= errfl[PARERR] | (~frame_error & parity_error);
        errfl[INVCOMM] <= errfl[INVCOMM] | (frame_good & bad_command);
        write_pending  <= 1'b0;
      end else if (write_pending) begin
        write_pending <= 1'b0;
        case (answer)
          R_PROG:      prog  <= rx[7:0];
          R_ZPOSM:     zposm <= rx[7:0];
          R_ZPOSL:     zposl <= rx[7:0];
          R_SETTINGS1: set1  <= rx[7:0];
          R_SETTINGS2: set2  <= rx[7:0];
          default:     ;
        endcase
      end else begin
        answer         <= named;
        write_pending  <= ~is_read & ~is_nop;
      end
    end
    if (rst) begin
      errfl          <= 3'd0;
      prog           <= 8'd0;
      zposm          <= ZERO_32[13:6];
      zposl          <= {2'b00, ZERO_32[5:0]};
      set1           <= S1_32[7:0];
      set2           <= S2_32[7:0];
      answer         <= R_ANGLECOM;
      write_pending  <= 1'b0;
      been_valid     <= 1'b0;
      held           <= 14'd0;
      tx             <= 16'd0;
      rx             <= 16'd0;
      clocks         <= 5'd0;
      frame_done     <= 1'b0;
    end
  end

  // The bit the master samples at SCLK's next falling edge: on the clock that sees an
  // edge, already the next one.
  assign miso      = bit_edge ? tx[14] : tx[15];
  assign miso_oe   = selected;
  assign zero      = zero_now;
  assign settings1 = set1;
  assign settings2 = set2;

endmodule

`resetall
