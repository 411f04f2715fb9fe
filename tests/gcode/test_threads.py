"""``on_two_threads``: the caller's thread and one more share the items."""

import threading

import pytest

from app.gcode.threads import on_two_threads


def test_results_come_in_the_items_order_worked_out_by_two_threads():
    both = threading.Barrier(2, timeout=10)  # neither goes on until the other has an item
    seen = []

    def work(item):
        if item < 2:
            both.wait()
        seen.append(threading.current_thread().name)
        return item * item

    assert on_two_threads(work, range(50), "squares") == [i * i for i in range(50)]
    assert {threading.current_thread().name, "squares"} == set(seen)


def test_no_items_and_one_item():
    assert on_two_threads(lambda item: item, []) == []
    assert on_two_threads(lambda item: item + 1, [1]) == [2]


def test_an_exception_is_raised_once_both_are_done():
    done = []

    def work(item):
        if item == 3:
            raise ValueError("item 3")
        done.append(item)

    with pytest.raises(ValueError, match="item 3"):
        on_two_threads(work, range(10))
    assert 3 not in done


def test_the_second_thread_waits_for_its_event():
    free = threading.Event()
    names = []
    assert on_two_threads(lambda item: names.append(threading.current_thread().name) or item, range(30),
                          "waits", second=free) == list(range(30))
    assert set(names) == {threading.current_thread().name}  # every item done here
    free.set()  # (the waiting thread then finds nothing left)

    free, both = threading.Event(), threading.Barrier(2, timeout=10)
    free.set()
    squares = on_two_threads(lambda item: both.wait() if item < 2 else item * item, range(6), second=free)
    assert squares[2:] == [4, 9, 16, 25]  # both threads met at the barrier: the second began
