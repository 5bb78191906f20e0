"""``python -m coopkin_sym`` runs the ``coopkin`` command."""

from .cli import main

main()
