// tb_sequencer -- self-checking Icarus bench of albatross_sequencer on the
// ROM of make_rom.py: every slot starts (go_o) exactly FETCH_CYCLES-1 clocks
// after cycle start + E1, may_access_o ends TIMEOUT+2 clocks before the
// deadline, cycles are 400 clocks, no ROM error; then one ROM word of entry 1
// is upset: the background check counts it and the entry is skipped.
// +bad_start0 (make_rom.py --bad-start0): entry 0's start does not fit
// TIME_BITS: entry 0 never goes, it counts in rom_errors every cycle, and
// the other entries keep their times.  +modes (make_rom.py --modes): the
// three entries are the start-up mode of an image with two modes: the same
// checks (an entry of the other mode that went would be "unexpected"), and
// the upset hits a mode descriptor.  +modes_bad (--modes-bad): an invalid
// H2: error_o and no go.  +modes_switch (--modes): requests switch to mode 1
// (two COPY entries of channel 3 at 20 and 150 in a 300-clock cycle) and
// back, mid-cycle: each switch happens at the next cycle boundary, and only
// there (the cycle length, the entries and mode_o of every cycle are those
// of one mode); a request for a mode that does not exist is rejected
// (mode_reject_o) and one for the running mode changes nothing.
`timescale 1ns/1ps
`default_nettype none
module tb_sequencer;
    reg clk = 0, rst = 1;
    always #5 clk = !clk;
    wire go, may, perr, cyc_s, error;
    wire [1:0] kind; wire [6:0] chan; wire [2:0] nd; wire [11:0] words;
    wire [3:0] sb; wire [9:0] sbase; wire [15:0] db; wire [39:0] dbase;
    wire [31:0] slot_time, t; wire [15:0] rerr, cycles;
    wire poll_cyc; wire [3:0] pb; wire [9:0] pa;
    reg done = 0;
    reg mreq = 0; reg [3:0] mreq_mode = 0;
    wire [3:0] mode; wire mreject;
    albatross_sequencer #(.NB(4), .ADDR_WIDTH(10), .N_CHAN(4), .ROM_WORDS(64), .ROM_FILE("seq_rom.hex"),
                          .TIME_BITS(12), .TIMEOUT(8), .POLL(16)) dut (
        .clk_i(clk), .rst_i(rst), .enable_i(1'b1),
        .go_o(go), .kind_o(kind), .chan_o(chan), .nd_o(nd), .words_o(words), .src_board_o(sb), .src_base_o(sbase),
        .dst_board_o(db), .dst_base_o(dbase), .slot_time_o(slot_time), .may_access_o(may), .slot_done_i(done),
        .poll_cyc_o(poll_cyc), .poll_board_o(pb), .poll_adr_o(pa), .poll_dat_i(32'd0), .poll_ack_i(1'b0),
        .poll_err_i(1'b0), .sync_rl_i(2'd0),
        .time_o(t), .cycle_o(cyc_s), .error_o(error), .rom_errors_o(rerr), .cycles_o(cycles),
        .mode_req_i(mreq), .mode_req_mode_i(mreq_mode), .mode_o(mode), .mode_reject_o(mreject));
    assign perr = 1'b0;
    integer cstart = -1, errors = 0, gos = 0, k, last_may, in_slot = 0, e0_gos = 0;
    integer starts [0:4]; integer lens [0:4];
    integer cur_mode = 0, cycles_in [0:1], rejects = 0;
    // mode 0: entries 0..2; mode 1: entries 3, 4 (make_rom.py --modes)
    function integer n_ent; input integer m; n_ent = m ? 2 : 3; endfunction
    function integer exp_kind; input integer m; input integer e; exp_kind = m ? 1 : e + 1; endfunction
    function integer ix; input integer m; input integer e; ix = m ? 3 + e : e; endfunction
    initial begin
        starts[0] = 10; starts[1] = 120; starts[2] = 200; lens[0] = 100; lens[1] = 60; lens[2] = 150;
        starts[3] = 20; starts[4] = 150; lens[3] = 60; lens[4] = 60; cycles_in[0] = 0; cycles_in[1] = 0;
        repeat (3) @(posedge clk);
        rst = 0;
    end
    always @(posedge clk) if (!rst) begin
        done <= 1'b0;
        if (mreject) rejects = rejects + 1;
        if (cyc_s) begin
            if (cstart >= 0 && t - cstart != (cur_mode ? 300 : 400)) begin
                $display("FAIL cycle length %0d in mode %0d, expected %0d", t - cstart, cur_mode, cur_mode ? 300 : 400);
                errors = errors + 1;
            end
            if (cstart >= 0 && k != n_ent(cur_mode) && !$test$plusargs("bad_start0")) begin
                $display("FAIL a cycle of mode %0d ran %0d of its %0d entries", cur_mode, k, n_ent(cur_mode));
                errors = errors + 1;
            end
            cstart = t; k = 0; cur_mode = mode;
            if (cur_mode > 1) begin $display("FAIL mode_o %0d: the image has modes 0 and 1", cur_mode); errors = errors + 1; end
            else cycles_in[cur_mode] = cycles_in[cur_mode] + 1;
        end
        if (go) begin
            while (k < n_ent(cur_mode) && !(kind == exp_kind(cur_mode, k))) k = k + 1;
            if (k >= n_ent(cur_mode)) begin $display("FAIL go of an unexpected entry (mode %0d)", cur_mode); errors = errors + 1; end
            else if (t != cstart + starts[ix(cur_mode, k)] + 6 || slot_time != cstart + starts[ix(cur_mode, k)] ||
                     (cur_mode == 1 && chan != 7'd3)) begin
                $display("FAIL entry %0d of mode %0d go at %0d, slot time %0d, channel %0d, expected %0d", k, cur_mode, t,
                         slot_time, chan, cstart + starts[ix(cur_mode, k)] + 6);
                errors = errors + 1;
            end
            gos = gos + 1; in_slot = 1;
            if (kind == 1) e0_gos = e0_gos + 1;
        end
        if (in_slot && may) last_may = t;
        if (in_slot && !may && !go) begin
            // the last access may go on the bus at last_may + 1 <= D - TIMEOUT - 2
            if (last_may + 1 != cstart + starts[ix(cur_mode, k)] + lens[ix(cur_mode, k)] - 10) begin
                $display("FAIL entry %0d last access clock %0d, expected %0d", k, last_may + 1,
                         cstart + starts[ix(cur_mode, k)] + lens[ix(cur_mode, k)] - 10);
                errors = errors + 1;
            end
            in_slot = 0; done <= 1'b1; k = k + 1;
        end
    end
    initial begin
        wait (!rst);
        repeat (3000) @(posedge clk);
        if ($test$plusargs("modes_bad")) begin
            if (!error || gos != 0) begin
                $display("FAIL modes header: expected error_o and no go for start_end beyond NE, came error %0d, gos %0d",
                         error, gos); errors = errors + 1; end
            $display("modes header with start_end beyond NE: error %0d, gos %0d", error, gos);
            if (errors == 0) $display("PASS tb_sequencer");
            $finish;
        end
        if ($test$plusargs("modes_switch")) begin
            // mid-cycle requests: to mode 1, an unknown mode 7, mode 1 again (running: nothing), back to 0
            repeat (37) @(posedge clk);
            mreq <= 1; mreq_mode <= 4'd1; @(posedge clk); mreq <= 0;
            repeat (1500) @(posedge clk);
            if (mode != 1 || cycles_in[1] < 3) begin
                $display("FAIL expected mode 1 after its request, came mode %0d, %0d cycles of mode 1", mode, cycles_in[1]);
                errors = errors + 1; end
            mreq <= 1; mreq_mode <= 4'd7; @(posedge clk); mreq <= 0; @(posedge clk); @(posedge clk);
            if (rejects != 1) begin $display("FAIL a request for mode 7 of 2: expected 1 rejection, came %0d", rejects);
                errors = errors + 1; end
            repeat (111) @(posedge clk);
            mreq <= 1; mreq_mode <= 4'd1; @(posedge clk); mreq <= 0;
            repeat (700) @(posedge clk);
            if (mode != 1 || rejects != 1) begin
                $display("FAIL a request for the running mode 1: expected mode 1 and no rejection, came mode %0d, %0d rejections",
                         mode, rejects); errors = errors + 1; end
            mreq <= 1; mreq_mode <= 4'd0; @(posedge clk); mreq <= 0;
            repeat (1500) @(posedge clk);
            if (mode != 0 || error || rerr != 0) begin
                $display("FAIL expected mode 0 again, no error: came mode %0d, error %0d, rom_errors %0d", mode, error, rerr);
                errors = errors + 1; end
            $display("modes: %0d cycles of mode 0, %0d of mode 1, %0d rejected", cycles_in[0], cycles_in[1], rejects);
            if (errors == 0) $display("PASS tb_sequencer");
            $finish;
        end
        if ($test$plusargs("bad_start0")) begin
            if (error || e0_gos != 0 || rerr < cycles - 1 || gos < 10)
                begin $display("FAIL bad entry-0 start: expected no go of entry 0, rom_errors >= cycles - 1 = %0d, gos >= 10; came error %0d, entry-0 gos %0d, rom_errors %0d, gos %0d",
                                cycles - 1, error, e0_gos, rerr, gos); errors = errors + 1; end
            $display("bad entry-0 start: skipped, rom_errors %0d in %0d cycles", rerr, cycles);
            if (errors == 0) $display("PASS tb_sequencer");
            $finish;
        end
        if (error || rerr != 0 || gos < 15) begin $display("FAIL error %0d rom_errors %0d gos %0d", error, rerr, gos); errors = errors + 1; end
        if ($test$plusargs("modes")) dut.u_rom.rom[4 + 8 * 5 + 2] = 32'h00001234;   // upset mode 0's descriptor (D2)
        else dut.u_rom.rom[4 + 8 + 3] = 32'h00001234;     // upset entry 1 (E3, unused by TIME)
        gos = 0;
        repeat (3000) @(posedge clk);
        if (rerr == 0) begin $display("FAIL upset not counted"); errors = errors + 1; end
        if (gos < 10) begin $display("FAIL gos %0d after the upset", gos); errors = errors + 1; end
        $display("rom_errors %0d cycles %0d after the upset", rerr, cycles);
        if (errors == 0) $display("PASS tb_sequencer");
        $finish;
    end
endmodule
`default_nettype wire
