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
#
# A harness's own source (a .cpp outside the object folder, compiled with
# -c) is cached too, by its preprocessed text: the same harness built
# against many mutants of one top (whose generated header is the same)
# compiles once.  The preprocessing pass also writes the dependency file
# that the compile would have written, so make's later decisions are the same.
set -u
src=${!#}
case "$src" in
    */include/verilated*.cpp) ;;
    /*.cpp|../*.cpp)
        harness=1 ;;
    *) exec "$@" ;;
esac
if [ "${harness-}" = 1 ]; then
    out= prev= mmd= pre=() key=()
    for a in "$@"; do
        if [ "$prev" = "-o" ]; then out=$a; prev=; continue; fi
        prev=$a
        case "$a" in
            -o) continue ;;
            -c) pre+=(-E); key+=(-c); continue ;;
            -MMD|-MD) mmd=$a ;;
        esac
        pre+=("$a"); key+=("$a")
    done
    case " $* " in *" -c "*) ;; *) exec "$@" ;; esac
    [ -n "$out" ] || exec "$@"
    root=$(cd "$(dirname "$0")/.." && pwd)
    dir=$root/build/objcache
    mkdir -p "$dir"
    tmp=$dir/.pre.$$.ii
    # (the dependency file named as the compile names it: out's stem + .d)
    "${pre[@]}" -o "$tmp" ${mmd:+-MF "${out%.*}.d" -MT "$out"} || { rm -f "$tmp"; exec "$@"; }
    h=$(printf '%s\n' "${key[@]}" "$(sha1sum < "$tmp")" | sha1sum | cut -c1-16)
    rm -f "$tmp"
    obj=$dir/$(basename "$src" .cpp)-$h.o
    if [ -f "$obj" ]; then
        cp "$obj" "$out"
        exit 0
    fi
    "$@" || exit
    cp "$out" "$obj.$$" && mv -f "$obj.$$" "$obj"
    exit 0
fi
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
