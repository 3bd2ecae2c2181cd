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
// H2: error_o and no go.
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
    albatross_sequencer #(.NB(4), .ADDR_WIDTH(10), .N_CHAN(4), .ROM_WORDS(64), .ROM_FILE("seq_rom.hex"),
                          .TIME_BITS(12), .TIMEOUT(8), .POLL(16)) dut (
        .clk_i(clk), .rst_i(rst), .enable_i(1'b1),
        .go_o(go), .kind_o(kind), .chan_o(chan), .nd_o(nd), .words_o(words), .src_board_o(sb), .src_base_o(sbase),
        .dst_board_o(db), .dst_base_o(dbase), .slot_time_o(slot_time), .may_access_o(may), .slot_done_i(done),
        .poll_cyc_o(poll_cyc), .poll_board_o(pb), .poll_adr_o(pa), .poll_dat_i(32'd0), .poll_ack_i(1'b0),
        .poll_err_i(1'b0), .sync_rl_i(2'd0),
        .time_o(t), .cycle_o(cyc_s), .error_o(error), .rom_errors_o(rerr), .cycles_o(cycles));
    assign perr = 1'b0;
    integer cstart = -1, errors = 0, gos = 0, k, last_may, in_slot = 0, e0_gos = 0;
    integer starts [0:2]; integer lens [0:2];
    initial begin
        starts[0] = 10; starts[1] = 120; starts[2] = 200; lens[0] = 100; lens[1] = 60; lens[2] = 150;
        repeat (3) @(posedge clk);
        rst = 0;
    end
    always @(posedge clk) if (!rst) begin
        done <= 1'b0;
        if (cyc_s) begin
            if (cstart >= 0 && t - cstart != 400) begin $display("FAIL cycle length %0d", t - cstart); errors = errors + 1; end
            cstart = t; k = 0;
        end
        if (go) begin
            while (k < 3 && !(kind == (k == 0 ? 1 : k == 1 ? 2 : 3))) k = k + 1;
            if (k >= 3) begin $display("FAIL go of an unexpected entry"); errors = errors + 1; end
            else if (t != cstart + starts[k] + 6 || slot_time != cstart + starts[k]) begin
                $display("FAIL entry %0d go at %0d, slot time %0d, expected %0d", k, t, slot_time, cstart + starts[k] + 6);
                errors = errors + 1;
            end
            gos = gos + 1; in_slot = 1;
            if (kind == 1) e0_gos = e0_gos + 1;
        end
        if (in_slot && may) last_may = t;
        if (in_slot && !may && !go) begin
            // the last access may go on the bus at last_may + 1 <= D - TIMEOUT - 2
            if (last_may + 1 != cstart + starts[k] + lens[k] - 10) begin
                $display("FAIL entry %0d last access clock %0d, expected %0d", k, last_may + 1, cstart + starts[k] + lens[k] - 10);
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
                $display("FAIL modes header: expected error_o and no go for start_end beyond the table, came error %0d, gos %0d",
                         error, gos); errors = errors + 1; end
            $display("modes header with start_end beyond the table: error %0d, gos %0d", error, gos);
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
