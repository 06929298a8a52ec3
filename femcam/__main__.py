"""``python -m femcam``: the command-line interface (nothing runs on a plain import)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
