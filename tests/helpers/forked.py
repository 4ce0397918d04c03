"""Work done in a child forked from the test process: a real process (its own limits, its own
pid, killable) without a fresh interpreter's start-up and imports, which cost 0.05-0.3 s a
child where the test process has them loaded already."""

from __future__ import annotations

import os
import pickle
import sys
import traceback
from collections.abc import Callable
from typing import TypeVar

T = TypeVar("T")


class ChildFailed(AssertionError):
    """The child's work raised: its traceback, as the child printed it."""


def in_a_child(work: Callable[[], T]) -> T:
    """``work()`` run in a child forked from this process; its result, sent back pickled. The
    child writes no byte-code (a limit on file sizes, set in ``work``, would cut a module's
    short) and never returns into the caller's code: it leaves by ``os._exit``."""
    read, write = os.pipe()
    child = os.fork()
    if child == 0:
        status = 0
        try:
            os.close(read)
            sys.dont_write_bytecode = True
            answer: object = work()
        except BaseException:
            answer, status = ChildFailed(traceback.format_exc()), 1
        finally:
            with os.fdopen(write, "wb") as pipe:
                pipe.write(pickle.dumps(answer))
            os._exit(status)
    os.close(write)
    with os.fdopen(read, "rb") as pipe:
        answer = pickle.loads(pipe.read())
    os.waitpid(child, 0)
    if isinstance(answer, ChildFailed):
        raise answer
    return answer  # type: ignore[no-any-return]
