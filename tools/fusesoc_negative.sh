#!/usr/bin/env bash
# fusesoc_negative.sh KIND -- a negative test of tools/fusesoc_check.py: a copy
# of the FuseSoC library (rtl/, c-driver/, tb/endpoint/tb_endpoint_loop.*) in
# build/fusesoc/neg-KIND/lib with one fault, which the check must reject with
# the message that names it.  Passes only if the check fails for that reason.
#   file    albatross_dpram.core names a file that does not exist (a typo)
#   dep     albatross_controller.core without its albatross:ip:contract dependency:
#           the controller's lint cannot find albatross_contract.vh
#   schema  albatross_bus.core with a misspelt key (filesets -> fileset): valid
#           YAML that FuseSoC refuses and skips with a mere warning
#   sim     the Export engine mutant export_early_publish (tb/mutants/engines/):
#           the simulation must FAIL on a torn value
set -u
kind=$1
work=build/fusesoc/neg-$kind
lib=$work/lib
rm -rf "$work"
mkdir -p "$lib/rtl" "$lib/tb/endpoint"
cp rtl/*.v rtl/*.vh rtl/*.core "$lib/rtl/"
cp -r c-driver "$lib/c-driver"
cp tb/endpoint/tb_endpoint_loop.v tb/endpoint/tb_endpoint_loop.core "$lib/tb/endpoint/"

mutate() {  # FILE SED-ARGS...: apply, and insist that it changed the file
    local f=$1; shift
    cp "$f" "$f.orig"
    sed -i "$@" "$f"
    if cmp -s "$f" "$f.orig"; then echo "fusesoc-negative: the $kind fault did not apply to $f"; exit 1; fi
    rm "$f.orig"
}
case $kind in
    file)   mutate "$lib/rtl/albatross_dpram.core" 's/- albatross_dpram\.v/- albatross_dpram_typo.v/'
            expect='names albatross_dpram_typo.v, expected the file' ;;
    dep)    mutate "$lib/rtl/albatross_controller.core" -e '/- albatross:ip:contract:/d' -e 's/^\( *\)depend:$/\1depend: []/'
            expect="Cannot find include file: .?albatross_contract\.vh" ;;
    schema) mutate "$lib/rtl/albatross_bus.core" 's/^filesets:/fileset:/'
            expect='expected FuseSoC to load core albatross:ip:bus' ;;
    sim)    mutate "$lib/rtl/albatross_export.v" -f tb/mutants/engines/export_early_publish.sed
            expect='FAIL untorn word' ;;
    *)      echo "fusesoc-negative: unknown kind $kind"; exit 1 ;;
esac

out=$("${PYTHON:-python3}" tools/fusesoc_check.py --root "$lib" --work "$work/check" --sim albatross:tb:endpoint_loop:1.0.0 2>&1)
rc=$?
echo "$out" | tail -n 15
if [ $rc -eq 0 ]; then
    echo "fusesoc-negative: expected the check to reject the $kind fault, it passed"; exit 1
fi
if ! echo "$out" | grep -Eq "$expect"; then
    echo "fusesoc-negative: the check failed, but expected the message /$expect/, got another"; exit 1
fi
echo "fusesoc-negative: the check rejected the $kind fault, as expected"
