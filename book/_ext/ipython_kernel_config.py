"""The IPython configuration of the kernels that execute the book's pages.

book/_ext/kernels.py copies this file into a profile of the book's own, next to the doctrees,
at every build. ``c`` is the configuration object IPython gives a config file.
"""

# ruff: noqa: F821
import logging


class _DropUnencryptedTcpNotice(logging.Filter):
    # ipykernel 7 logs, once per page, that its local TCP sockets are unencrypted. The kernel
    # lives as long as one page and talks only to the build on localhost; the message is
    # dropped, by its exact text, and every other log line of the kernel still shows.
    def filter(self, record):
        return not str(record.msg).startswith("Kernel is running over TCP without encryption")


logging.getLogger("IPKernelApp").addFilter(_DropUnencryptedTcpNotice())


class _DropShutdownRace(logging.Filter):
    # A finished kernel shutting down can run a ZMQStream callback on a socket it has just
    # closed (ZMQError ENOTSOCK, logged with a traceback by tornado). ipykernel 7.4 demotes the
    # iopub case of this race to debug (ipykernel PR 1518); this drops the same error on the
    # other streams, and nothing else that tornado logs.
    def filter(self, record):
        import zmq

        error = record.exc_info[1] if record.exc_info else None
        return not (isinstance(error, zmq.ZMQError) and error.errno == zmq.ENOTSOCK)


logging.getLogger("tornado.general").addFilter(_DropShutdownRace())
# Figures as SVG, sharp on any screen (HiDPI) and zoomable; the library leaves rcParams alone.
c.InlineBackend.figure_formats = {"svg"}
# No IPython history database for the throw-away kernels.
c.HistoryManager.enabled = False
