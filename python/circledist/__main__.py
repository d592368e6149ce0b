# SPDX-License-Identifier: MIT
"""``python -m circledist [OPTION...] [FILE...]``: the circledist command-line tool.

Runs the tool installed with this package (the same program, so the options, the output and
the exit status are the tool's own); ``python -m circledist --help`` lists them."""
import os
import sys

from ._lib import tool_path


def main(argv=None):
    """Replace this process by the circledist tool with the given arguments."""
    args = sys.argv[1:] if argv is None else list(argv)
    tool = tool_path()
    if tool is None:
        sys.stderr.write("circledist: the circledist tool was not installed with this package "
                         "(build with -Dtool=true) and is not on PATH\n")
        return 2
    sys.stdout.flush()
    os.execv(tool, [tool] + args)
    return 2  # not reached


if __name__ == "__main__":
    sys.exit(main())
