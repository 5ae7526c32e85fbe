"""Python's habits around a long solve: the GIL is released (two optimisations in two threads
run at once), Ctrl+C and the progress callback stop a solve with its best iterate, and an
exception raised in the callback reaches the caller."""

import os
import signal
import sys
import threading

import pytest

import saltus
from conftest import M1, M2

# A short solve: knots at the keyframes, a few dozen iterations (a second or less).
SHORT = dict(knots_per_interval=1, max_iter=40, joint_load_weight=0.0)


def test_two_optimisations_in_two_threads_run_at_the_same_time():
    # With a switch interval this long Python never takes the GIL from a thread that holds it:
    # had the module kept the GIL while the library computes, one thread's whole solve would run
    # before the other's first iteration. Iterations of both solves interleave only because the
    # GIL is released.
    events = []
    results = {}

    def run(name, path):
        results[name] = saltus.optimize(path, progress=lambda p: events.append(name), **SHORT)

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        threads = [threading.Thread(target=run, args=(n, p)) for n, p in (("a", M1), ("b", M2))]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(interval)
    first_b, last_a = events.index("b"), len(events) - 1 - events[::-1].index("a")
    assert first_b < last_a, "the solves ran one after the other: the GIL was held"
    # And each thread's result is the one a solve alone gives.
    for name, path in (("a", M1), ("b", M2)):
        alone = saltus.optimize(path, **SHORT)
        assert results[name].result["after"] == alone.result["after"], name


def test_ctrl_c_cancels_and_returns_the_best_iterate():
    seen = []

    def interrupt_at_the_third(p):
        seen.append(p.iteration)
        if len(seen) == 3:
            os.kill(os.getpid(), signal.SIGINT)  # what Ctrl+C sends

    r = saltus.optimize(M1, progress=interrupt_at_the_third, knots_per_interval=1)
    assert r.cancelled and r.status == "cancelled"
    assert len(seen) <= 4  # stopped after the current iteration
    assert r.after.average_root_force < r.before.average_root_force
    assert len(r.after.times) == len(r.before.times)  # a complete result


def test_stop_iteration_in_the_callback_cancels():
    def stop(p):
        if p.iteration >= 2:
            raise StopIteration

    r = saltus.optimize(M1, progress=stop, knots_per_interval=1)
    assert r.cancelled and r.iterations <= 3


def test_another_exception_in_the_callback_reaches_the_caller():
    def broken(p):
        raise RuntimeError("the callback broke")

    with pytest.raises(RuntimeError, match="the callback broke"):
        saltus.optimize(M1, progress=broken, **SHORT)
    with pytest.raises(saltus.InputError, match="progress"):
        saltus.optimize(M1, progress=3)


def test_progress_reports_every_iteration_in_order():
    seen = []
    r = saltus.optimize(M1, progress=seen.append, **SHORT)
    assert [p.iteration for p in seen] == sorted(p.iteration for p in seen)
    assert all(p.elapsed_seconds >= 0 and p.constraint_violation >= 0 for p in seen)
    assert len(seen) >= r.iterations
