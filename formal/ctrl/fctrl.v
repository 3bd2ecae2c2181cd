// fctrl -- proof harness of albatross_controller on its own RTL, a black box
// seen only at its Wishbone master port (formal/ctrl/ctrl.sby,
// docs/verification.md "The controller on its own RTL").  There is no copy
// of the controller's glue here: the device under test is the controller's
// top with its import and export engines, bus master, per-channel state RAM
// and counters; only its sequencer is replaced by the sequencer's contract
// (formal/ctrl/fseq_contract.v, a free environment; the sequencer itself is
// proved by formal/sequencer).  Configuration: ADDR_WIDTH = AW, N_CHAN = 1
// (every slot is a redundant slot of one channel), TIMEOUT = 3, one COPY
// entry with ND = 2: the source on board 1, destinations on boards 2 and 3,
// every base free, W = 1 .. 2**WW - 1 free, the drop run K = 0..3 free (0 and
// 1 read as 2), the channel kind free or fixed by F_FOUR (1 four-slot, 0
// three-buffer).
// Environment: reset in the first clock only; the bus answers freely (ack,
// err or nothing in any clock of a request, never both), a store without ack
// may land in any clock of its request (land_i: its answer lost or err'd);
// the source's producer and the destinations' consumers are free within
// their protocols (formal/alb/falb_src.v, falb_dst.v).
// Properties: those of the observers (formal/alb/falb_src.v, falb_dst.v,
// falb_slot.v; Wishbone classic: formal/wb/fwb_master.v with OPT_ABORT, the
// bus master withdraws a timed-out request) and
//   bus_board   every request goes to the source's or a destination's board.
// Actuality (the paper's fourth proof point) is falb_src's src_fresh, for
// both kinds: an Import that starts (s_go) after the producer completed a
// value returns that value or a newer one; an Old answer while a newer value
// is there loads the older copy's words for the destinations in need, which
// src_fresh refuses (negatives old_same_pair4 and old_same_pair3: an Import
// that answers Old whenever Actual lies in the pair of its copy).
// With F_SHAPE the load data are free and only the access shapes are checked
// (the observers' PROTO = 0): the proof of the bus rules, the slot timing, the
// retry and drop rule and every access's place and lanes, without the
// producer's and consumers' state.
// With F_FRAG (and F_FIXED: W = 2) the value may go over several runs
// (fseq_contract's frag_on_o = 1; a run stores words until the value's end
// or the free deadline; the negatives: formal/ctrl/tests.mk): a slot goes
// on with the value when the controller's state says so at go (f_on and
// the progress f_prog, its state RAM, joined by the script), else it
// starts a value (s_vgo).  The observers take s_vgo as their slot start (an
// Import and an Export span the value's runs), and
//   frag_words_src, frag_words_dst  every source word load and destination
//               word store of a run that goes on is of a word at or after
//               the progress (the run resumes at the right word, never
//               before it; a word skipped leaves a buffer incomplete, which
//               dst_publish_complete refuses), and a destination's taken_at
//               store comes only after its store of the value's last word
//               was answered in the same run;
//   frag_held   a slot that goes on with a value makes no access to the
//               source's control word (its ReadLocked stays held from the
//               first run to the last);
//   frag_prog   a slot goes on with a value only from a word of it after
//               its first (0 < progress < W);
// with falb_dst's dst_publish_complete (an Actual store only of a buffer
// whose words were all stored since the value's start) nothing is
// published before the last fragment, and dst_no_held_write keeps every
// store out of the buffer the consumer holds.
// Covers: cov_new, cov_old (a New / an Old Import read the source), cov_pub0,
// cov_pub1 (each destination published), cov_drop, cov_retry, cov_readback
// (a destination's Actual store whose answer was lost, seen landed by the
// control-word load of a later slot).
`default_nettype none

module fctrl #(
    parameter AW = 4,   // word-address bits of a board RAM
    parameter WW = 2    // bits of W
) (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        ack_i,
    input  wire        err_i,
    input  wire        land_i,
    input  wire [31:0] rdat_i,     // load data of the words the observers do not keep
    input  wire [1:0]  p_op_i,     // the source's producer
    input  wire [2:0]  p_wb_i,
    input  wire        p_watch_i,
    input  wire [1:0]  c0_op_i,    // the destinations' consumers
    input  wire [1:0]  c1_op_i
);
    localparam BB = 4, TIMEOUT = 3;
`ifdef F_SHAPE
    localparam PROTO = 0;      // F_SHAPE: free load data, the access shapes only
`else
    localparam PROTO = 1;
`endif

    wire          m_cyc, m_stb, m_we;
    wire [AW+3:0] m_adr;
    wire [3:0]    m_sel;
    wire [31:0]   m_wdat;
    reg  [31:0]   m_rdat;
    wire [31:0]   time_o;
    wire          error_o;
    wire [15:0]   rom_errors;

    albatross_controller #(.NB(4), .ADDR_WIDTH(AW), .N_CHAN(1), .ROM_WORDS(12), .TIMEOUT(TIMEOUT),
                           .TIME_BITS(8)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .m_cyc_o(m_cyc), .m_stb_o(m_stb), .m_we_o(m_we), .m_adr_o(m_adr), .m_sel_o(m_sel),
        .m_dat_o(m_wdat), .m_dat_i(m_rdat), .m_ack_i(ack_i), .m_err_i(err_i),
        .time_o(time_o), .error_o(error_o), .rom_errors_o(rom_errors));

    // The entry and the sequencer's slot signals: joined by the script to
    // fseq_contract's free constants and outputs (Yosys has no hierarchical
    // references); they are the environment, not the device under test.
    (* keep *) wire [11:0]   e_words;
    (* keep *) wire          e_four;
    (* keep *) wire [AW-1:0] e_src_base, e_dst_base0, e_dst_base1;
    (* keep *) wire [7:0]    e_drop_run;
    (* keep *) wire          s_go, s_may;
    (* keep *) wire [11:0]   f_prog;         // the controller's progress of channel 0 (its state RAM)
    (* keep *) wire          f_on;           // ... and its flag: a value goes on
`ifdef F_FRAG
    // a slot goes on with the value when the state says so at go
    wire          s_cont = s_go && f_on;
    wire          s_vgo  = s_go && !s_cont;
`else
    wire          s_vgo  = s_go;
    wire          unused_prog = &{1'b0, f_prog, f_on};
`endif
    wire [WW-1:0] w = e_words[WW-1:0];

    wire        s_hit, s_rl, s_wl, d0_hit, d0_ctrl, d0_pub, d1_hit, d1_ctrl, d1_pub;
    wire [31:0] s_ctrl, d0_word, d1_word;
    wire        s_carry;
    reg         carry_q;                   // this slot's Import read the watched value
    wire [2:0]  d0_held, d0_act, d1_held, d1_act;
    falb_src #(.AW(AW), .WW(WW), .BB(BB), .PROTO(PROTO), .BOARD(1)) src (
        .clk_i(clk_i), .rst_i(rst_i), .base_i(e_src_base), .words_i(w), .four_i(e_four),
        .cyc_i(m_cyc), .stb_i(m_stb), .we_i(m_we), .adr_i(m_adr), .sel_i(m_sel), .wdat_i(m_wdat),
        .ack_i(ack_i), .land_i(land_i), .op_i(p_op_i), .wb_i(p_wb_i),
        .slot_start_i(s_vgo), .watch_i(p_watch_i), .carry_o(s_carry),
        .ctrl_o(s_ctrl), .hit_o(s_hit), .rl_store_o(s_rl), .word_load_o(s_wl));
    falb_dst #(.AW(AW), .WW(WW), .BB(BB), .PROTO(PROTO), .WHOLE_LOAD(1), .BOARD(2)) dst0 (
        .clk_i(clk_i), .rst_i(rst_i), .slot_start_i(s_vgo), .base_i(e_dst_base0), .words_i(w), .four_i(e_four),
        .cyc_i(m_cyc), .stb_i(m_stb), .we_i(m_we), .adr_i(m_adr), .sel_i(m_sel), .wdat_i(m_wdat),
        .ack_i(ack_i), .land_i(land_i), .op_i(c0_op_i), .carry_i(carry_q),
        .ctrl_o(d0_word), .hit_o(d0_hit), .ctrl_hit_o(d0_ctrl), .pub_o(d0_pub), .held_o(d0_held), .act_o(d0_act));
    falb_dst #(.AW(AW), .WW(WW), .BB(BB), .PROTO(PROTO), .WHOLE_LOAD(1), .BOARD(3)) dst1 (
        .clk_i(clk_i), .rst_i(rst_i), .slot_start_i(s_vgo), .base_i(e_dst_base1), .words_i(w), .four_i(e_four),
        .cyc_i(m_cyc), .stb_i(m_stb), .we_i(m_we), .adr_i(m_adr), .sel_i(m_sel), .wdat_i(m_wdat),
        .ack_i(ack_i), .land_i(land_i), .op_i(c1_op_i), .carry_i(carry_q),
        .ctrl_o(d1_word), .hit_o(d1_hit), .ctrl_hit_o(d1_ctrl), .pub_o(d1_pub), .held_o(d1_held), .act_o(d1_act));

    wire       fail, retry;
    wire [1:0] dropped;
    falb_slot #(.AW(AW+4), .BB(BB), .ND(2), .TIMEOUT(TIMEOUT)) slot (
        .clk_i(clk_i), .rst_i(rst_i), .go_i(s_go), .may_i(s_may), .drop_run_i(e_drop_run),
        .dst_board_i({4'd3, 4'd2}),
        .cyc_i(m_cyc), .stb_i(m_stb), .we_i(m_we), .adr_i(m_adr), .sel_i(m_sel), .wdat_i(m_wdat),
        .ack_i(ack_i), .err_i(err_i), .fail_o(fail), .retry_o(retry), .dropped_o(dropped));

    always @(posedge clk_i) begin
        if (rst_i || s_vgo) carry_q <= 1'b0;
        else if (s_carry) carry_q <= 1'b1;
    end

    // the load data: the control words the observers keep, else free
    wire s_ctrl_hit = s_hit && m_adr[AW-1:0] == e_src_base;
    always @* begin
        m_rdat = rdat_i;
        if (PROTO != 0) begin
            if (s_ctrl_hit) m_rdat = s_ctrl;
            if (d0_ctrl)    m_rdat = d0_word;
            if (d1_ctrl)    m_rdat = d1_word;
        end
    end

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;
    wire req = m_cyc && m_stb;
    always @* begin
        assume(rst_i == init_q);
        assume(e_words[11:WW] == 0 && e_words != 12'd0);
        assume(e_drop_run <= 8'd3);
`ifdef F_FOUR
        assume(e_four == (`F_FOUR != 0));
`endif
        if (!req) assume(!land_i);
    end

    wire       f_pv, f_out, f_rack;
    wire [3:0] f_wait;
    fwb_master #(.AW(AW+4), .DW(32), .OPT_ABORT(1)) wb (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(m_cyc), .stb_i(m_stb), .we_i(m_we), .adr_i(m_adr),
        .sel_i(m_sel), .wdat_i(m_wdat), .rdat_i(m_rdat), .ack_i(ack_i), .err_i(err_i),
        .f_past_valid_o(f_pv), .f_outstanding_o(f_out), .f_wait_o(f_wait), .f_read_ack_o(f_rack));

    always @* if (!init_q) bus_board: assert(!req || s_hit || d0_hit || d1_hit);

`ifdef F_FRAG
    // ------------------------------------------------------------ runs (W = 2)
    reg          cont_q;
    reg [WW-1:0] p_q;                      // the run's first word: 0, or the progress at go
    reg [1:0]    last_q;                   // destination d's store of the last word (1) answered in this run
    // word offsets of the access in its buffer: source stride 2, destination stride 3
    wire [AW-1:0] s_off = m_adr[AW-1:0] - e_src_base - 1'b1;
    wire [AW-1:0] d_off = m_adr[AW-1:0] - (d0_hit ? e_dst_base0 : e_dst_base1) - 1'b1;
    wire [AW-1:0] d_m   = d_off % 3;       // 0, 1: value words; 2: taken_at
    wire          d_wst = (d0_hit && !d0_ctrl || d1_hit && !d1_ctrl) && m_we;   // a destination word store
    always @(posedge clk_i) begin
        if (rst_i) begin
            cont_q <= 1'b0;
            p_q    <= {WW{1'b0}};
            last_q <= 2'b00;
        end else if (s_go) begin
            cont_q <= s_cont;
            p_q    <= s_cont ? f_prog[WW-1:0] : {WW{1'b0}};
            last_q <= 2'b00;
        end else if (req && ack_i && d_wst && d_m == 1) begin
            last_q <= last_q | (d0_hit ? 2'b01 : 2'b10);
        end
    end
    always @* begin
        if (!init_q && req) begin
            if (s_hit && !m_we && m_adr[AW-1:0] != e_src_base)
                frag_words_src: assert(s_off[0] >= p_q[0]);
            if (d_wst)
                frag_words_dst: assert(d_m == 2 ? (d0_hit ? last_q[0] : last_q[1]) : d_m[0] >= p_q[0]);
            if (cont_q)
                frag_held: assert(!(s_hit && m_adr[AW-1:0] == e_src_base));
        end
        // a value goes on only from a word of it after its first
        if (!init_q && s_cont) frag_prog: assert(f_prog != 12'd0 && f_prog < e_words);
    end
`endif

    // ------------------------------------------------------------ covers
    reg rl_slot_q, wl_slot_q, lost_q, later_q;
    reg [2:0] lost_b;
    always @(posedge clk_i) begin
        if (rst_i || s_go) begin
            rl_slot_q <= 1'b0;
            wl_slot_q <= 1'b0;
        end else begin
            if (s_rl) rl_slot_q <= 1'b1;
            if (s_wl) wl_slot_q <= 1'b1;
        end
        if (rst_i) begin
            lost_q  <= 1'b0;
            later_q <= 1'b0;
        end else begin
            if (d0_ctrl && m_we && m_sel == 4'b0001 && land_i && !ack_i && !lost_q) begin
                lost_q <= 1'b1;
                lost_b <= m_wdat[2:0];
            end
            if (lost_q && s_go) later_q <= 1'b1;
        end
    end
    always @* begin
        if (!init_q) begin
            cov_new:      cover(s_wl && rl_slot_q);
            cov_old:      cover(s_wl && !rl_slot_q);
            cov_pub0:     cover(d0_pub);
            cov_pub1:     cover(d1_pub);
            cov_drop:     cover(dropped != 2'b00);
            cov_retry:    cover(retry);
            cov_watch:    cover(d1_pub && carry_q);
            cov_readback: cover(later_q && d0_ctrl && !m_we && ack_i && d0_act == lost_b);
        end
    end
`endif
endmodule

`default_nettype wire
