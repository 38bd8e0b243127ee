"""python3 -m stylize_parameters (with scripts/ on the path): the same as scripts/parameters.py."""
import sys

from .main import main

sys.exit(main())
