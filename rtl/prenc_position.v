// prenc_position: the position the reader holds, counted from the quadrature and
// placed on the disc by the converter.
//
// An incremental slot count follows the quadrature decoder: +1 on a CW step into
// q = 0 (a slot boundary crossed CW), -1 on a CCW step into q = 3. It never jumps,
// and an illegal transition does not move it. When the code word becomes full, its
// converted slot p and the slot count at the strobe that completed it give the
// offset between the count and the disc; from then on
//   pos_abs = slot count + offset (mod 2^N),  pos_hyb = 4 * pos_abs + q.
// Whether that position is verified is the mode state machine's business.
//
// Timing: the word after a strobe on clock k is converted on clock k+2; the slot
// count of that strobe is carried alongside (word_slot, then word_slot_d).
//
// Parameters
//   N   code word length, 2..24
//
// Ports
//   quarter, step, step_cw   from prenc_quadrature
//   strobe                   from prenc_sampler
//   word_full                from prenc_shift_register
//   conv_valid, conv_pos     from prenc_converter (its input: the word, word_full)
//   slot                     incremental slot count (mod 2^N); at a strobe, the
//                            strobe's slot
//   hyp_ready                the offset of the current word is loaded, or loads now
//   pos_abs                  absolute slot p (registered count + offset)
//   pos_hyb                  hybrid position 4p + q, coherent with pos_abs

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_position #(
  parameter integer N = 10
) (
  input  wire         clk,
  input  wire         rst,
  input  wire [1:0]   quarter,
  input  wire         step,
  input  wire         step_cw,
  input  wire         strobe,
  input  wire         word_full,
  input  wire         conv_valid,
  input  wire [N-1:0] conv_pos,
  output wire [N-1:0] slot,
  output wire         hyp_ready,
  output wire [N-1:0] pos_abs,
  output wire [N+1:0] pos_hyb
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_position_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  reg [N-1:0] slot_reg;
  reg [1:0]   quarter_reg;
  reg [N-1:0] word_slot_reg;
  reg [N-1:0] word_slot_d_reg;
  reg [N-1:0] offset_reg;
  reg         hyp_valid_reg;

  wire load = conv_valid & ~hyp_valid_reg;

  always @(posedge clk) begin
    quarter_reg     <= quarter;
    word_slot_d_reg <= word_slot_reg;
    if (step && step_cw && quarter == 2'd0) begin
      slot_reg <= slot_reg + 1'b1;
    end else if (step && !step_cw && quarter == 2'd3) begin
      slot_reg <= slot_reg - 1'b1;
    end
    if (strobe) begin
      word_slot_reg <= slot_reg;
    end
    if (load) begin
      offset_reg    <= conv_pos - word_slot_d_reg;
      hyp_valid_reg <= 1'b1;
    end
    if (!word_full) begin
      hyp_valid_reg <= 1'b0;
    end
    if (rst) begin
      slot_reg        <= {N{1'b0}};
      quarter_reg     <= 2'd0;
      word_slot_reg   <= {N{1'b0}};
      word_slot_d_reg <= {N{1'b0}};
      offset_reg      <= {N{1'b0}};
      hyp_valid_reg   <= 1'b0;
    end
  end

  assign slot      = slot_reg;
  assign hyp_ready = hyp_valid_reg | load;
  assign pos_abs   = slot_reg + offset_reg;
  assign pos_hyb   = {pos_abs, quarter_reg};

endmodule

`resetall
