"""python3 -m albatross_schedule DESCRIPTION.toml --out DIR  (compiler/ on PYTHONPATH)."""

import sys

from .cli import main

sys.exit(main())
