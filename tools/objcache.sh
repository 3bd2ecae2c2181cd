#!/usr/bin/env bash
# objcache.sh CXX ARGS... -- Verilator's OBJCACHE (tools/mk/suite.mk exports
# it): every `verilator --build` compiles Verilator's run-time library
# (verilated.cpp, verilated_threads.cpp, ...: about 8 s of CPU time) into its
# own object folder, and the suite has dozens of such folders.  For those
# files only, this keeps one object per distinct command line in
# build/objcache/ and copies it instead of compiling again.  The key is the
# command line without the output's name and without -D macros that are
# not Verilator's own (VM_*, VL_*): the run-time library reads no other
# macro, so a harness's own -DNAME=... need not split the cache; the object
# is compiled without them too, so that it is the same whoever asks first.
# Any other file is compiled as asked.
set -u
src=${!#}
case "$src" in
    */include/verilated*.cpp) ;;
    *) exec "$@" ;;
esac
args=() key=() out=
prev=
for a in "$@"; do
    if [ "$prev" = "-o" ]; then out=$a; args+=("$a"); prev=; continue; fi
    prev=$a
    case "$a" in
        -D*) case "$a" in -DVM_*|-DVL_*|-D_GNU_SOURCE) ;; *) continue ;; esac ;;
        -MMD|-MP) continue ;;                     # no dependency file: the library does not change
    esac
    args+=("$a")
    [ "$a" = "-o" ] || key+=("$a")
done
[ -n "$out" ] || exec "$@"
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$root/build/objcache
mkdir -p "$dir"
h=$(printf '%s\n' "${key[@]}" "$(cat "$src" | sha1sum)" | sha1sum | cut -c1-16)
obj=$dir/$(basename "$src" .cpp)-$h.o
if [ ! -f "$obj" ]; then
    "${args[@]}" || exit
    cp "$out" "$obj.$$" && mv -f "$obj.$$" "$obj"
else
    cp "$obj" "$out"
fi
