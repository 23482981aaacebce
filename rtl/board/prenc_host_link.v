// SPDX-License-Identifier: Apache-2.0
// prenc_host_link: the board's side of the host protocol (docs/host-protocol.md).
//
// A UART (prenc_uart_rx / prenc_uart_tx), a frame parser and a frame sender, and the
// protocol engine between them and the reader core:
//
//   request  01 READ   kind            one answer of that kind
//            02 STREAM kind, period    answers of that kind every `period` us
//                                      (big-endian, 4 bytes; 0 stops: one STATUS)
//            03 CLEAR                  clears every error counter, answers STATUS
//            04 WRITE_CAL address[3], word[2]   a word of the calibration table (CAL = 1),
//                                      answers STATUS
//   answer   80+kind, payload = FLAGS, SEQ, TIME[4], data of the kind
//            kind 0 ABS    pos_abs, 2 bytes        kind 1 HYBRID  pos_hyb, 3 bytes
//            kind 2 INCR   incremental, 4 bytes    kind 3 TRACKS  t1, t2 (2 bytes), flags
//            kind 4 STATUS version, N, track1/track2/sync/link error counters (2 bytes each)
//            kind 5 FINE   fine position (4 bytes), velocity (4, quarters per clock x 2^32),
//                          info (bits 3:0 FINE_BITS, 4 velocity valid, 5 interpolated),
//                          the clock in MHz (1)
//            kind 6 EDGES  info (bit 7 lost, 6 direction CW, 5 pos_valid, 1:0 run), the run's
//                          first edge (3 bytes), 3 intervals (2 bytes each, clocks; 0 past
//                          the run): prenc_edge_capture's run, taken by the answer
//            kind 7 HEALTH pos_abs (2 bytes), track1/track2/sync error counters (2 bytes
//                          each), warnings (bit 0 head 1, 1 head 2, 2 sync): streamed, where
//                          on the disc the corrections happen (`prenc host map`)
//            FF NACK       code (1 unknown type, 2 bad length, 3 unknown kind, 4 no
//                          calibration table, 5 address out of range), request type
//   FLAGS    bit 7 pos_valid, bits 6:4 mode, bit 3 direction, bit 2 streaming, bit 1
//            warning (any of prenc_health's warnings: the corrections grow; docs/health.md)
//   SEQ      counts answers (mod 256); TIME microseconds since reset (mod 2^32)
//
// An answer's data are the core's outputs on the clock its frame starts (`snapshot`).
// A request that arrives while an answer is being sent waits for it; a streamed
// answer that falls due while another is being sent goes out right after it, so a
// period shorter than a frame streams back to back at the link's rate.
//
// Latency: an answer's data are the core's outputs on the clock its frame starts, after
// the request frame has been checked (or when a streamed answer falls due); the answer
// then takes its bytes' time on the line, 10 bit times a byte.
//
// Parameters
//   N         code word length of the core, 4..16
//   CLK_HZ    clock frequency, a multiple of 1 MHz (for TIME and the stream period)
//   BAUD      UART baud rate; CLK_HZ / BAUD >= 4 and the rounding error <= 2 %
//   CAL       1: the board has a calibration table (WRITE_CAL writes it); 0: NACK 4
//
// Ports
//   clk, rst               one clock; synchronous active-high reset
//   rx, tx                 the UART lines
//   pos_abs ... sync_errors   the core's outputs (warnings: prenc_health's)
//   fine_pos, velocity, fine_info   prenc_fine's (FINE): the fine position zero-extended,
//                          the velocity word, {2'b0, interpolated, velocity_valid, FINE_BITS}
//   edge_*                 prenc_edge_capture's run; edge_take, one clock: the run is taken
//   cal_write, cal_address, cal_data   a word of the calibration table (WRITE_CAL)
//   clear_errors           one clock, to the core (CLEAR)
//   link_errors            rejected request frames since reset or CLEAR
//   snapshot               one clock: an answer starts, with the core's values of this clock

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_host_link #(
  parameter integer N      = 10,
  parameter integer CLK_HZ = 24000000,
  parameter integer BAUD   = 115200,
  parameter integer CAL    = 0
) (
  input  wire          clk,
  input  wire          rst,
  input  wire          rx,
  output wire          tx,
  input  wire [N-1:0]  pos_abs,
  input  wire [N+1:0]  pos_hyb,
  input  wire          pos_valid,
  input  wire [2:0]    mode,
  input  wire          direction,
  input  wire [2:0]    warnings,
  input  wire [31:0]   incremental,
  input  wire [N-1:0]  track1_pos,
  input  wire          track1_valid,
  input  wire [N-1:0]  track2_pos,
  input  wire          track2_valid,
  input  wire [15:0]   track1_errors,
  input  wire [15:0]   track2_errors,
  input  wire [15:0]   sync_errors,
  input  wire [31:0]   fine_pos,
  input  wire [31:0]   velocity,
  input  wire [7:0]    fine_info,
  input  wire [1:0]    edge_run,
  input  wire          edge_valid,
  input  wire          edge_cw,
  input  wire [N+1:0]  edge_first,
  input  wire [15:0]   edge_interval0,
  input  wire [15:0]   edge_interval1,
  input  wire [15:0]   edge_interval2,
  input  wire          edge_lost,
  output wire          edge_take,
  output wire          cal_write,
  output wire [N+1:0]  cal_address,
  output wire [15:0]   cal_data,
  output wire          clear_errors,
  output wire [15:0]   link_errors,
  output wire          snapshot
);

  localparam integer CLKS_PER_BIT = (CLK_HZ + BAUD / 2) / BAUD;
  localparam integer CLKS_PER_US  = CLK_HZ / 1000000;
  localparam integer RATE_ERROR   = (CLKS_PER_BIT * BAUD > CLK_HZ) ? CLKS_PER_BIT * BAUD - CLK_HZ
                                                                   : CLK_HZ - CLKS_PER_BIT * BAUD;

  generate
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_host_link_parameter_CAL_must_be_0_or_1 u_stop ();
    end
    if (N < 4 || N > 16) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 4..16", N);
      prenc_host_link_parameter_N_out_of_range_4_to_16 u_stop ();
    end
    if (CLK_HZ < 1000000 || CLK_HZ % 1000000 != 0) begin : g_bad_clk_hz
      initial $display("ERROR: %m: parameter CLK_HZ = %0d must be a multiple of 1 MHz", CLK_HZ);
      prenc_host_link_parameter_CLK_HZ_not_a_multiple_of_1_MHz u_stop ();
    end
    if (BAUD < 1 || CLK_HZ / BAUD < 4) begin : g_bad_baud
      initial $display("ERROR: %m: parameter BAUD = %0d needs CLK_HZ / BAUD >= 4 (CLK_HZ = %0d)",
                       BAUD, CLK_HZ);
      prenc_host_link_parameter_BAUD_too_high_for_CLK_HZ u_stop ();
    end else if (RATE_ERROR * 50 > CLK_HZ) begin : g_bad_rate
      initial $display("ERROR: %m: parameter BAUD = %0d is more than 2 %% off at CLK_HZ = %0d",
                       BAUD, CLK_HZ);
      prenc_host_link_parameter_BAUD_not_reachable_within_2_percent u_stop ();
    end
  endgenerate

  localparam [7:0]  VERSION     = 8'd4;
  localparam [31:0] CLK_MHZ     = CLK_HZ / 1000000;
  localparam [31:0] N_32        = N;
  localparam [31:0] US_LIMIT_32 = CLKS_PER_US - 1;
  localparam [15:0] US_LIMIT    = US_LIMIT_32[15:0];

  localparam [7:0] REQ_READ   = 8'h01;
  localparam [7:0] REQ_STREAM = 8'h02;
  localparam [7:0] REQ_CLEAR  = 8'h03;
  localparam [7:0] REQ_WRITE  = 8'h04;
  localparam [7:0] ANS_DATA   = 8'h80;
  localparam [7:0] ANS_NACK   = 8'hFF;
  localparam [2:0] KIND_STAT  = 3'd4;

  // --- UART and framing -------------------------------------------------------
  wire [7:0]  rx_byte;
  wire        rx_byte_valid;
  wire        rx_byte_error;
  wire        rx_busy;
  wire        req_valid;
  wire [7:0]  req_type;
  wire [7:0]  req_len;
  wire [39:0] req_payload;
  wire        req_error;
  wire [7:0]  tx_byte;
  wire        tx_byte_start;
  wire        tx_byte_ready;
  wire        tx_busy;

  prenc_uart_rx #(
    .CLKS_PER_BIT (CLKS_PER_BIT)
  ) u_uart_rx (
    .clk         (clk),
    .rst         (rst),
    .rx          (rx),
    .data        (rx_byte),
    .valid       (rx_byte_valid),
    .frame_error (rx_byte_error),
    .busy        (rx_busy)
  );

  prenc_frame_rx #(
    .MAX_LEN (5),
    .TIMEOUT (20 * CLKS_PER_BIT)
  ) u_frame_rx (
    .clk           (clk),
    .rst           (rst),
    .byte_data     (rx_byte),
    .byte_valid    (rx_byte_valid),
    .byte_error    (rx_byte_error),
    .frame_valid   (req_valid),
    .frame_type    (req_type),
    .frame_len     (req_len),
    .frame_payload (req_payload),
    .frame_error   (req_error)
  );

  // --- Protocol engine -----------------------------------------------------------
  reg [15:0]  us_timer;
  reg [31:0]  time_us;
  reg         us_tick;
  reg         pending;        // an answer to a request is waiting
  reg [7:0]   pending_type;   // 80+kind or FF
  reg [7:0]   nack_code;
  reg [7:0]   nack_of;
  reg         clear_reg;
  reg         clearing;       // CLEAR's answer waits one clock for the counters
  reg         streaming;
  reg [2:0]   stream_kind;
  reg [31:0]  stream_period;
  reg [31:0]  stream_wait;
  reg         stream_due;
  reg [7:0]   seq;
  reg [15:0]  link_errors_reg;
  reg         start_reg;
  reg [7:0]   start_type;
  reg         cal_write_reg;
  reg [N+1:0] cal_address_reg;
  reg [15:0]  cal_data_reg;

  wire [2:0]  req_kind   = req_payload[2:0];
  wire        kind_ok    = (req_payload[7:3] == 5'd0);   // kinds 0..7, all answered
  wire [31:0] req_period = {req_payload[15:8], req_payload[23:16],
                            req_payload[31:24], req_payload[39:32]};
  wire        can_start  = ~tx_busy & ~start_reg;
  // WRITE_CAL: the address (3 bytes) and the word (2), big-endian.
  wire [23:0] req_address = {req_payload[7:0], req_payload[15:8], req_payload[23:16]};
  wire [15:0] req_word    = {req_payload[31:24], req_payload[39:32]};
  wire        address_ok  = (req_address >> (N + 2)) == 24'd0;

  always @(posedge clk) begin
    // Time base.
    us_tick <= 1'b0;
    if (us_timer == US_LIMIT) begin
      us_timer <= 16'd0;
      us_tick  <= 1'b1;
    end else begin
      us_timer <= us_timer + 16'd1;
    end
    if (us_tick) begin
      time_us <= time_us + 32'd1;
    end

    // Stream timer.
    if (streaming && us_tick) begin
      if (stream_wait + 32'd1 >= stream_period) begin
        stream_wait <= 32'd0;
        stream_due  <= 1'b1;
      end else begin
        stream_wait <= stream_wait + 32'd1;
      end
    end

    // Requests.
    clear_reg     <= 1'b0;
    cal_write_reg <= 1'b0;
    clearing  <= clear_reg;
    if (req_error && link_errors_reg != 16'hFFFF) begin
      link_errors_reg <= link_errors_reg + 16'd1;
    end
    if (req_valid) begin
      pending      <= 1'b1;
      nack_of      <= req_type;
      pending_type <= ANS_NACK;
      if (req_type == REQ_READ) begin
        if (req_len != 8'd1) begin
          nack_code <= 8'd2;
        end else if (!kind_ok) begin
          nack_code <= 8'd3;
        end else begin
          pending_type <= ANS_DATA | {5'd0, req_kind};
        end
      end else if (req_type == REQ_STREAM) begin
        if (req_len != 8'd5) begin
          nack_code <= 8'd2;
        end else if (!kind_ok) begin
          nack_code <= 8'd3;
        end else if (req_period == 32'd0) begin
          streaming    <= 1'b0;
          stream_due   <= 1'b0;
          pending_type <= ANS_DATA | {5'd0, KIND_STAT};
        end else begin
          streaming     <= 1'b1;
          stream_kind   <= req_kind;
          stream_period <= req_period;
          stream_wait   <= 32'd0;
          stream_due    <= 1'b0;
          pending_type  <= ANS_DATA | {5'd0, req_kind};
        end
      end else if (req_type == REQ_CLEAR) begin
        if (req_len != 8'd0) begin
          nack_code <= 8'd2;
        end else begin
          clear_reg       <= 1'b1;
          link_errors_reg <= 16'd0;
          pending_type    <= ANS_DATA | {5'd0, KIND_STAT};
        end
      end else if (req_type == REQ_WRITE) begin
        cal_address_reg <= req_address[N+1:0];
        cal_data_reg    <= req_word;
        if (req_len != 8'd5) begin
          nack_code <= 8'd2;
        end else if (CAL == 0) begin
          nack_code <= 8'd4;
        end else if (!address_ok) begin
          nack_code <= 8'd5;
        end else begin
          cal_write_reg   <= 1'b1;
          pending_type    <= ANS_DATA | {5'd0, KIND_STAT};
        end
      end else begin
        nack_code <= 8'd1;
      end
    end

    // Answers: a waiting request first, then the stream.
    start_reg <= 1'b0;
    if (can_start && pending && !req_valid && !clear_reg && !clearing) begin
      pending    <= 1'b0;
      start_reg  <= 1'b1;
      start_type <= pending_type;
    end else if (can_start && stream_due && streaming && !pending) begin
      stream_due <= 1'b0;
      start_reg  <= 1'b1;
      start_type <= ANS_DATA | {5'd0, stream_kind};
    end
    if (start_reg) begin
      seq <= seq + 8'd1;
    end

    if (rst) begin
      us_timer        <= 16'd0;
      us_tick         <= 1'b0;
      time_us         <= 32'd0;
      pending         <= 1'b0;
      clear_reg       <= 1'b0;
      clearing        <= 1'b0;
      streaming       <= 1'b0;
      stream_due      <= 1'b0;
      seq             <= 8'd0;
      link_errors_reg <= 16'd0;
      start_reg       <= 1'b0;
      cal_write_reg   <= 1'b0;
    end
  end

  // The answer, built from this clock's core outputs when start_reg is high.
  wire [7:0] flags = {pos_valid, mode, direction, streaming, |warnings, 1'b0};
  reg [15:0] abs16;
  reg [23:0] hyb24;
  reg [15:0] t1_16;
  reg [15:0] t2_16;
  reg [23:0] edge24;

  always @* begin
    abs16 = 16'd0;
    hyb24 = 24'd0;
    t1_16 = 16'd0;
    t2_16 = 16'd0;
    edge24 = 24'd0;
    edge24[N+1:0] = edge_first;
    abs16[N-1:0] = pos_abs;
    hyb24[N+1:0] = pos_hyb;
    t1_16[N-1:0] = track1_pos;
    t2_16[N-1:0] = track2_pos;
  end

  reg [8*16-1:0] payload;
  reg [7:0]      length;

  always @* begin
    payload = {8*16{1'b0}};
    payload[7:0]   = flags;
    payload[15:8]  = seq;
    payload[23:16] = time_us[31:24];
    payload[31:24] = time_us[23:16];
    payload[39:32] = time_us[15:8];
    payload[47:40] = time_us[7:0];
    length = 8'd6;
    case (start_type)
      ANS_DATA | 8'd0: begin
        payload[55:48] = abs16[15:8];
        payload[63:56] = abs16[7:0];
        length = 8'd8;
      end
      ANS_DATA | 8'd1: begin
        payload[55:48] = hyb24[23:16];
        payload[63:56] = hyb24[15:8];
        payload[71:64] = hyb24[7:0];
        length = 8'd9;
      end
      ANS_DATA | 8'd2: begin
        payload[55:48] = incremental[31:24];
        payload[63:56] = incremental[23:16];
        payload[71:64] = incremental[15:8];
        payload[79:72] = incremental[7:0];
        length = 8'd10;
      end
      ANS_DATA | 8'd3: begin
        payload[55:48] = t1_16[15:8];
        payload[63:56] = t1_16[7:0];
        payload[71:64] = t2_16[15:8];
        payload[79:72] = t2_16[7:0];
        payload[87:80] = {6'd0, track2_valid, track1_valid};
        length = 8'd11;
      end
      ANS_DATA | 8'd4: begin
        payload[55:48]   = VERSION;
        payload[63:56]   = N_32[7:0];
        payload[71:64]   = track1_errors[15:8];
        payload[79:72]   = track1_errors[7:0];
        payload[87:80]   = track2_errors[15:8];
        payload[95:88]   = track2_errors[7:0];
        payload[103:96]  = sync_errors[15:8];
        payload[111:104] = sync_errors[7:0];
        payload[119:112] = link_errors_reg[15:8];
        payload[127:120] = link_errors_reg[7:0];
        length = 8'd16;
      end
      ANS_DATA | 8'd5: begin
        payload[55:48]   = fine_pos[31:24];
        payload[63:56]   = fine_pos[23:16];
        payload[71:64]   = fine_pos[15:8];
        payload[79:72]   = fine_pos[7:0];
        payload[87:80]   = velocity[31:24];
        payload[95:88]   = velocity[23:16];
        payload[103:96]  = velocity[15:8];
        payload[111:104] = velocity[7:0];
        payload[119:112] = fine_info;
        payload[127:120] = CLK_MHZ[7:0];
        length = 8'd16;
      end
      ANS_DATA | 8'd6: begin
        payload[55:48]   = {edge_lost, edge_cw, edge_valid, 3'b000, edge_run};
        payload[63:56]   = edge24[23:16];
        payload[71:64]   = edge24[15:8];
        payload[79:72]   = edge24[7:0];
        payload[87:80]   = edge_interval0[15:8];
        payload[95:88]   = edge_interval0[7:0];
        payload[103:96]  = edge_interval1[15:8];
        payload[111:104] = edge_interval1[7:0];
        payload[119:112] = edge_interval2[15:8];
        payload[127:120] = edge_interval2[7:0];
        length = 8'd16;
      end
      ANS_DATA | 8'd7: begin
        payload[55:48]   = abs16[15:8];
        payload[63:56]   = abs16[7:0];
        payload[71:64]   = track1_errors[15:8];
        payload[79:72]   = track1_errors[7:0];
        payload[87:80]   = track2_errors[15:8];
        payload[95:88]   = track2_errors[7:0];
        payload[103:96]  = sync_errors[15:8];
        payload[111:104] = sync_errors[7:0];
        payload[119:112] = {5'd0, warnings};
        length = 8'd15;
      end
      default: begin  // NACK
        payload[55:48] = nack_code;
        payload[63:56] = nack_of;
        length = 8'd8;
      end
    endcase
  end

  prenc_frame_tx #(
    .MAX_LEN (16)
  ) u_frame_tx (
    .clk           (clk),
    .rst           (rst),
    .start         (start_reg),
    .frame_type    (start_type),
    .frame_len     (length),
    .frame_payload (payload),
    .busy          (tx_busy),
    .byte_data     (tx_byte),
    .byte_start    (tx_byte_start),
    .byte_ready    (tx_byte_ready)
  );

  prenc_uart_tx #(
    .CLKS_PER_BIT (CLKS_PER_BIT)
  ) u_uart_tx (
    .clk   (clk),
    .rst   (rst),
    .data  (tx_byte),
    .start (tx_byte_start),
    .ready (tx_byte_ready),
    .tx    (tx)
  );

  wire unused_ok = &{1'b0, rx_busy, req_payload[7:3]};

  assign edge_take    = start_reg && (start_type == (ANS_DATA | 8'd6));
  assign cal_write    = cal_write_reg;
  assign cal_address  = cal_address_reg;
  assign cal_data     = cal_data_reg;
  assign clear_errors = clear_reg;
  assign link_errors  = link_errors_reg;
  assign snapshot     = start_reg;

endmodule

`resetall
