"""``python -m mechkit ARGS...``: the ``mechkit`` command."""

from ._cli import main

main()
