"""python -m albatross_schedule DESCRIPTION.toml -o DIR: the same as the albatross-schedule command."""

import sys

from .cli import main

sys.exit(main())
