#!/usr/bin/env python3
"""run_axil.py -- build and run the cocotb test tb/axil/test_axil.py under Icarus
(tools/mk/axil.mk).

    run_axil.py NAME [--adapter FILE] [--ops N] [--seed S] [--expect-fail TEXT]
                [--report JSON] [--timeout SECONDS]

Builds tb/axil/tb_axil.v, rtl/albatross_dpram_axil.v, the AXI4-Lite adapter
(default rtl/albatross_axil2native.v; a mutant for the negative test) and
rtl/albatross_dpram_core.v into build/axil/NAME/, runs the test (cocotb 2.x
runner, Icarus; cocotb 2 would need a newer Verilator than 5.006) and checks its
verdict.  --expect-fail TEXT: the test must fail, with TEXT in its log (the
checker caught the fault it guards against); otherwise it must pass.
"""
import argparse
import os
import sys
import time

from cocotb_tools.runner import get_results, get_runner

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("--adapter", default="rtl/albatross_axil2native.v")
    ap.add_argument("--ops", type=int, default=1500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--expect-fail", default=None)
    ap.add_argument("--report", default=None)
    ap.add_argument("--timeout", type=int, default=300)
    args = ap.parse_args()

    build = os.path.join(ROOT, "build", "axil", args.name)
    os.makedirs(build, exist_ok=True)
    srcs = [os.path.join(ROOT, f) for f in ("tb/axil/tb_axil.v", "rtl/albatross_dpram_axil.v",
                                           args.adapter, "rtl/albatross_dpram_core.v")]
    runner = get_runner("icarus")
    runner.build(sources=srcs, hdl_toplevel="tb_axil", build_dir=build, always=True,
                 build_args=["-g2005"], timescale=("1ns", "1ps"), log_file=os.path.join(build, "build.log"))
    env = {"AXIL_OPS": str(args.ops), "AXIL_SEED": str(args.seed)}
    if args.report:
        env["AXIL_REPORT"] = os.path.abspath(args.report)
        os.makedirs(os.path.dirname(env["AXIL_REPORT"]), exist_ok=True)
    log = os.path.join(build, "test.log")
    t0 = time.time()
    xml = runner.test(test_module="test_axil", hdl_toplevel="tb_axil", build_dir=build,
                      test_dir=os.path.join(ROOT, "tb", "axil"), extra_env=env, log_file=log,
                      results_xml=os.path.join(build, "results.xml"))
    secs = time.time() - t0
    ntests, nfail = get_results(xml)
    text = open(log, errors="replace").read()
    fig = [l for l in text.splitlines() if "axil figures:" in l]
    if fig:
        print(fig[-1].split("axil figures:", 1)[1].strip())
    if args.expect_fail is None:
        if ntests == 1 and nfail == 0:
            print(f"{args.name}: cocotb test passed ({secs:.0f} s)")
            return 0
        errs = [l for l in text.splitlines() if "AssertionError" in l or "mismatch" in l or "expected" in l]
        print(f"{args.name}: expected the cocotb test to pass, it failed ({nfail} of {ntests}); log: {log}")
        for l in errs[:5]:
            print("  " + l.strip())
        return 1
    if nfail == 0:
        print(f"{args.name}: expected a failure containing '{args.expect_fail}', the test passed; log: {log}")
        return 1
    # the failure itself (an AssertionError line), not the source line in the traceback
    caught = [l for l in text.splitlines() if "AssertionError: " + args.expect_fail in l]
    if not caught:
        print(f"{args.name}: the test failed, but not with '{args.expect_fail}'; log: {log}")
        return 1
    first = caught[0]
    print(f"{args.name}: the broken variant is caught, as expected ({secs:.0f} s): {first.strip()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
