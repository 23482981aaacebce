// SPDX-License-Identifier: Apache-2.0
// prenc_frame_rx: the host link's frame parser, bytes in, checked frames out.
//
// Frame (docs/host-protocol.md):  A5 | TYPE | LEN | PAYLOAD[LEN] | CRC16 hi | lo
// CRC-16/CCITT-FALSE (prenc_crc16) over TYPE, LEN and the payload.
//
// The parser hunts for the start byte A5, then follows the length. A frame is
// rejected, with one `frame_error` pulse, when its CRC differs, its LEN exceeds
// MAX_LEN, a byte inside it has a framing error, or the line stays idle for
// TIMEOUT clocks inside it; the parser then hunts for the next A5. Bytes between
// frames are ignored and not counted. The timeout is what resynchronises after a
// corrupted LEN: the host waits for an answer (far longer than TIMEOUT) before it
// sends again, so the parser is hunting again when the next frame starts.
//
// Latency: frame_valid or frame_error one clock after the byte that ends the frame (the
// second CRC byte) comes from the UART.
//
// Parameters
//   MAX_LEN   largest payload accepted, 1..16 bytes
//   TIMEOUT   idle clocks that abort a frame, >= 1 (the board uses 2 byte times)
//
// Ports
//   clk, rst            one clock; synchronous active-high reset
//   byte_data, byte_valid, byte_error   from prenc_uart_rx
//   frame_valid         one clock: a frame passed its CRC
//   frame_type, frame_len, frame_payload   that frame (payload byte i at [8i+7:8i],
//                       bytes past LEN are zero); held until the next frame
//   frame_error         one clock: a frame was rejected

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_frame_rx #(
  parameter integer MAX_LEN = 5,
  parameter integer TIMEOUT = 1000
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire [7:0]             byte_data,
  input  wire                   byte_valid,
  input  wire                   byte_error,
  output wire                   frame_valid,
  output wire [7:0]             frame_type,
  output wire [7:0]             frame_len,
  output wire [8*MAX_LEN-1:0]   frame_payload,
  output wire                   frame_error
);

  generate
    if (MAX_LEN < 1 || MAX_LEN > 16) begin : g_bad_max_len
      initial $display("ERROR: %m: parameter MAX_LEN = %0d is out of range 1..16", MAX_LEN);
      prenc_frame_rx_parameter_MAX_LEN_out_of_range_1_to_16 u_stop ();
    end
    if (TIMEOUT < 1 || TIMEOUT > 16777215) begin : g_bad_timeout
      initial $display("ERROR: %m: parameter TIMEOUT = %0d is out of range 1..16777215", TIMEOUT);
      prenc_frame_rx_parameter_TIMEOUT_out_of_range_1_to_16777215 u_stop ();
    end
  endgenerate

  localparam [7:0]  SOF        = 8'hA5;
  localparam [31:0] MAX_LEN_32 = MAX_LEN;
  localparam [7:0]  MAX_LEN_8  = MAX_LEN_32[7:0];
  localparam [31:0] TIMEOUT_32 = TIMEOUT - 1;
  // idle counts up to TIMEOUT - 1 in a frame
  localparam integer IW        = (TIMEOUT < 2) ? 1 : $clog2(TIMEOUT);
  localparam [IW-1:0] IDLE_LIMIT = TIMEOUT_32[IW-1:0];

  localparam [2:0] HUNT    = 3'd0;
  localparam [2:0] TYPE    = 3'd1;
  localparam [2:0] LEN     = 3'd2;
  localparam [2:0] PAYLOAD = 3'd3;
  localparam [2:0] CRC_HI  = 3'd4;
  localparam [2:0] CRC_LO  = 3'd5;

  reg [2:0]             state;
  reg [7:0]             type_reg;
  reg [7:0]             len_reg;
  reg [7:0]             index;
  reg [8*MAX_LEN-1:0]   payload;
  reg [15:0]            crc;
  reg [7:0]             crc_hi;
  reg [IW-1:0]          idle;
  reg                   valid_reg;
  reg                   error_reg;
  reg [7:0]             out_type;
  reg [7:0]             out_len;
  reg [8*MAX_LEN-1:0]   out_payload;

  wire [15:0] crc_next;

  prenc_crc16 u_crc (
    .crc_in  (crc),
    .data    (byte_data),
    .crc_out (crc_next)
  );

  always @(posedge clk) begin
    valid_reg <= 1'b0;
    error_reg <= 1'b0;
    if (state != HUNT) begin
      idle <= idle + 1'b1;
    end
    if (state != HUNT && (byte_error || (!byte_valid && idle == IDLE_LIMIT))) begin
      state     <= HUNT;
      error_reg <= 1'b1;
    end else if (byte_valid) begin
      idle <= {IW{1'b0}};
      case (state)
        HUNT: begin
          if (byte_data == SOF) begin
            state   <= TYPE;
            crc     <= 16'hFFFF;
            payload <= {8*MAX_LEN{1'b0}};
          end
        end
        TYPE: begin
          type_reg <= byte_data;
          crc      <= crc_next;
          state    <= LEN;
        end
        LEN: begin
          len_reg <= byte_data;
          crc     <= crc_next;
          index   <= 8'd0;
          if (byte_data > MAX_LEN_8) begin
            state     <= HUNT;
            error_reg <= 1'b1;
          end else if (byte_data == 8'd0) begin
            state <= CRC_HI;
          end else begin
            state <= PAYLOAD;
          end
        end
        PAYLOAD: begin
          payload <= payload | ({{8*MAX_LEN-8{1'b0}}, byte_data} << {index, 3'b000});
          crc     <= crc_next;
          index   <= index + 8'd1;
          if (index + 8'd1 == len_reg) begin
            state <= CRC_HI;
          end
        end
        CRC_HI: begin
          crc_hi <= byte_data;
          state  <= CRC_LO;
        end
        default: begin  // CRC_LO
          state <= HUNT;
          if ({crc_hi, byte_data} == crc) begin
            valid_reg   <= 1'b1;
            out_type    <= type_reg;
            out_len     <= len_reg;
            out_payload <= payload;
          end else begin
            error_reg <= 1'b1;
          end
        end
      endcase
    end
    if (rst) begin
      state       <= HUNT;
      idle        <= {IW{1'b0}};
      valid_reg   <= 1'b0;
      error_reg   <= 1'b0;
      out_type    <= 8'd0;
      out_len     <= 8'd0;
      out_payload <= {8*MAX_LEN{1'b0}};
    end
  end

  assign frame_valid   = valid_reg;
  assign frame_type    = out_type;
  assign frame_len     = out_len;
  assign frame_payload = out_payload;
  assign frame_error   = error_reg;

`ifdef FORMAL
  // Properties (formal/prenc_frame_rx.sby). The CRC-16/CCITT-FALSE of what the frame
  // has carried so far (polynomial 0x1021, start 0xFFFF, MSB first: written here from
  // the definition, not taken from prenc_crc16), over TYPE, LEN and the payload.
  // A frame is accepted only when its two CRC bytes equal it; after any input,
  // TIMEOUT clocks without a byte leave the parser hunting for A5.
  function automatic [15:0] f_crc_byte;
    input [15:0] c;
    input [7:0]  d;
    integer k;
    begin
      f_crc_byte = c;
      for (k = 7; k >= 0; k = k - 1) begin
        f_crc_byte = (f_crc_byte[15] ^ d[k]) ? ({f_crc_byte[14:0], 1'b0} ^ 16'h1021)
                                             : {f_crc_byte[14:0], 1'b0};
      end
    end
  endfunction
  reg        f_past_valid = 1'b0;
  reg        f_rst_prev;
  reg [15:0] f_crc;      // the reference CRC of the frame's bytes so far
  reg [7:0]  f_crc_hi;   // the frame's first CRC byte
  reg [7:0]  f_last;     // the last byte received
  reg [7:0]  f_type;
  reg [7:0]  f_len;
  reg [23:0] f_quiet = 24'd0;  // clocks without a byte (saturating)
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_rst_prev   <= rst;
    f_quiet <= (byte_valid || byte_error) ? 24'd0 :
               (f_quiet == 24'hFFFFFF) ? f_quiet : f_quiet + 24'd1;
    if (byte_valid) begin
      f_last <= byte_data;
      if (state == HUNT) f_crc <= 16'hFFFF;
      if (state == TYPE || state == LEN || state == PAYLOAD) f_crc <= f_crc_byte(f_crc, byte_data);
      if (state == TYPE) f_type <= byte_data;
      if (state == LEN) f_len <= byte_data;
      if (state == CRC_HI) f_crc_hi <= byte_data;
    end
  end
  // The clock after a frame's last byte: accepted exactly when its CRC matches,
  // rejected (one frame_error) exactly when it does not; an error only ends a frame.
  reg f_closing;
  reg f_match;
  reg f_in_frame;
  always @(posedge clk) begin
    f_closing  <= byte_valid && !byte_error && state == CRC_LO;
    f_match    <= ({f_crc_hi, byte_data} == f_crc);
    f_in_frame <= (state != HUNT);
  end
  initial assume (rst);
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      if (f_closing) assert (frame_valid == f_match && frame_error == !f_match);
      if (frame_error) assert (f_in_frame);
      if (f_sending) assert (!frame_error);
    end
  end
  always @(*) begin
    if (f_past_valid) assume (!rst);
    if (f_past_valid && !f_rst_prev) begin
      // Accepted: the CRC bytes received equal the reference, and the outputs are the
      // frame's TYPE and LEN.
      if (frame_valid) assert ({f_crc_hi, f_last} == f_crc && frame_type == f_type &&
                               frame_len == f_len);
      // Invariants of the parse (what makes the proof inductive).
      if (state != HUNT && state != TYPE) assert (crc == f_crc);
      if (state == PAYLOAD) assert (index < len_reg && len_reg <= MAX_LEN_8 && len_reg == f_len);
      if (state == CRC_HI || state == CRC_LO) assert (len_reg == f_len && type_reg == f_type);
      if (state == LEN || state == PAYLOAD) assert (type_reg == f_type);
      // It cannot lock up.
      if (state != HUNT) assert (idle <= IDLE_LIMIT && idle <= f_quiet);
      if (f_quiet > IDLE_LIMIT) assert (state == HUNT);
    end
  end
  // A good frame after any input: once the line has been quiet for the timeout, a
  // sender sends A5, TYPE, LEN (up to MAX_LEN), the payload and its CRC, one byte a
  // clock (values chosen by the solver); the parser accepts it with its TYPE and LEN.
  (* anyconst *) reg [7:0] f_s_type;
  (* anyconst *) reg [7:0] f_s_len;
  (* anyconst *) reg [7:0] f_s_data;     // every payload byte
  (* anyseq *)   reg       f_go;
  reg        f_sending;
  reg [7:0]  f_k;        // bytes sent
  reg [15:0] f_s_crc;    // the sender's CRC so far
  reg        f_s_done;   // the last byte went out on the last clock
  reg [7:0]  f_s_byte;
  always @(*) begin
    if (f_k == 8'd0) f_s_byte = SOF;
    else if (f_k == 8'd1) f_s_byte = f_s_type;
    else if (f_k == 8'd2) f_s_byte = f_s_len;
    else if (f_k < 8'd3 + f_s_len) f_s_byte = f_s_data;
    else if (f_k == 8'd3 + f_s_len) f_s_byte = f_s_crc[15:8];
    else f_s_byte = f_s_crc[7:0];
  end
  always @(posedge clk) begin
    f_s_done <= 1'b0;
    if (!f_sending && f_go && f_quiet > IDLE_LIMIT && !byte_valid && !byte_error && !rst) begin
      f_sending <= 1'b1;
      f_k       <= 8'd0;
      f_s_crc   <= 16'hFFFF;
    end else if (f_sending) begin
      if (f_k >= 8'd1 && f_k < 8'd3 + f_s_len) f_s_crc <= f_crc_byte(f_s_crc, f_s_byte);
      f_k <= f_k + 8'd1;
      if (f_k == 8'd4 + f_s_len) begin
        f_sending <= 1'b0;
        f_s_done  <= 1'b1;
      end
    end
    if (rst) f_sending <= 1'b0;
  end
  initial assume (!f_sending);
  reg [8*MAX_LEN-1:0] f_s_payload;  // LEN copies of the payload byte, zeros past LEN
  integer f_b;
  always @(*) begin
    for (f_b = 0; f_b < MAX_LEN; f_b = f_b + 1) begin
      f_s_payload[8*f_b +: 8] = (f_b < f_s_len) ? f_s_data : 8'd0;
    end
  end
  always @(*) begin
    assume (f_s_len <= MAX_LEN_8);
    if (f_sending) assume (byte_valid && !byte_error && byte_data == f_s_byte);
    if (f_past_valid && !f_rst_prev && f_s_done)
      assert (frame_valid && frame_type == f_s_type && frame_len == f_s_len &&
              frame_payload == f_s_payload);
    // The parse follows the sender byte by byte (what makes the proof inductive).
    if (f_past_valid && !f_rst_prev && f_sending) begin
      if (f_k == 8'd0) assert (state == HUNT);
      if (f_k == 8'd1) assert (state == TYPE);
      if (f_k == 8'd2) assert (state == LEN && type_reg == f_s_type);
      if (f_k >= 8'd3 && f_k < 8'd3 + f_s_len)
        assert (state == PAYLOAD && index == f_k - 8'd3 && len_reg == f_s_len);
      if (f_k == 8'd3 + f_s_len) assert (state == CRC_HI && len_reg == f_s_len);
      if (f_k == 8'd4 + f_s_len) assert (state == CRC_LO && crc_hi == f_s_crc[15:8]);
      if (f_k >= 8'd1) assert (crc == f_s_crc);
      if (f_k >= 8'd3) assert (type_reg == f_s_type && f_len == f_s_len);
      for (f_b = 0; f_b < MAX_LEN; f_b = f_b + 1) begin
        if (f_k >= 8'd1) assert (payload[8*f_b +: 8] == ((f_b + 3 < f_k && f_b < f_s_len) ?
                                                        f_s_data : 8'd0));
      end
      assert (f_k <= 8'd4 + f_s_len);
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) cover (frame_valid && frame_len == MAX_LEN_8);
  end
`endif

endmodule

`resetall
