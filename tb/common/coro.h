// coro.h -- minimal stackful coroutine for simulated CPUs.
//
// A simulated CPU runs ordinary C code (the driver) on its own stack and
// hands control back to the clock loop at every RAM access.  The first entry
// uses makecontext/swapcontext; every later switch is _setjmp/_longjmp (no
// signal-mask system call: about 10x cheaper, see ../shared/TOOLCHAIN.md).
// Files using it must be built with -U_FORTIFY_SOURCE (checked longjmp
// aborts on a stack switch).
#pragma once
#include <csetjmp>
#include <cstdlib>
#include <ucontext.h>
#include <vector>

class Coro {
public:
    typedef void (*Entry)(void *arg);

    explicit Coro(std::size_t stack_bytes = 256 * 1024) : stack_(stack_bytes) {}

    // (Re)start: the next resume() enters entry(arg) on a fresh stack.  Any
    // state of a previous run is abandoned (a CPU reset).
    void start(Entry entry, void *arg) {
        entry_ = entry;
        arg_ = arg;
        started_ = false;
        finished_ = false;
    }

    // Run until the coroutine yields or its entry returns.
    void resume() {
        if (finished_ || entry_ == nullptr) return;
        if (_setjmp(caller_) == 0) {
            if (!started_) {
                started_ = true;
                getcontext(&ctx_);
                ctx_.uc_stack.ss_sp = stack_.data();
                ctx_.uc_stack.ss_size = stack_.size();
                ctx_.uc_link = nullptr;
                makecontext(&ctx_, reinterpret_cast<void (*)()>(&Coro::trampoline), 1, this);
                ucontext_t here;
                swapcontext(&here, &ctx_);
            } else {
                _longjmp(self_, 1);
            }
        }
    }

    // Called from inside the coroutine: back to whoever resumed it.
    void yield() {
        if (_setjmp(self_) == 0) _longjmp(caller_, 1);
    }

    bool finished() const { return finished_; }

private:
    static void trampoline(Coro *c) {
        c->entry_(c->arg_);
        c->finished_ = true;
        _longjmp(c->caller_, 1);
    }

    std::vector<char> stack_;
    ucontext_t ctx_{};
    std::jmp_buf caller_{}, self_{};
    Entry entry_ = nullptr;
    void *arg_ = nullptr;
    bool started_ = false, finished_ = false;
};
