# SPDX-License-Identifier: MIT
"""Ctrl-C during a C call that runs with the GIL released (internal module)."""
import signal
import threading


class SigintRecorder:
    """A temporary SIGINT handler that only records the signal while a C call runs.

    The call's own callback (a progress report, a block of scene pairs) reads ``hits`` and asks
    the library to stop; after the call ``deliver()`` runs the handler that was replaced, as if
    the signal had arrived then. Python runs a signal handler when a ctypes callback is entered,
    before the callback's own ``try``: the default handler's KeyboardInterrupt would escape into
    ctypes, which prints it and carries on. Only in the main thread (where Python handles
    signals) and only over a handler set in Python (not SIG_IGN, SIG_DFL or one set in C).
    """

    def __init__(self):
        on_main = threading.current_thread() is threading.main_thread()
        self.old = signal.getsignal(signal.SIGINT) if on_main else None
        self.catching = callable(self.old)
        self.hits = []

    def __enter__(self):
        if self.catching:
            signal.signal(signal.SIGINT, lambda signum, frame: self.hits.append(signum))
        return self

    def __exit__(self, *exc):
        if self.catching:
            signal.signal(signal.SIGINT, self.old)
        return False

    def deliver(self):
        """Run the replaced handler for a recorded Ctrl-C (the default one raises
        KeyboardInterrupt); True when one was recorded and the handler returned."""
        if not self.hits:
            return False
        if self.old is signal.default_int_handler:
            raise KeyboardInterrupt
        self.old(signal.SIGINT, None)
        return True
