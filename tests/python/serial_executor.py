"""An executor that runs each job at once, on this thread: sweeps in a known order, for the
tests that compare their rows or files."""


class Serial:
    """An executor that runs each job at once, on this thread."""

    class Done:
        def __init__(self, value):
            self.value = value

        def result(self):
            return self.value

        def cancel(self):
            return False

    def submit(self, fn, *args):
        return Serial.Done(fn(*args))
