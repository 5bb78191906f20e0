"""``python -m coopkin_sym`` runs the ``coopkin`` command."""

from coopkin_sym.cli import main

main()
