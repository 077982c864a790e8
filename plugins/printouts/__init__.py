"""Printout layout plugins (option 164): GEOUT1-GEOUT4 (manual §3.5)."""
