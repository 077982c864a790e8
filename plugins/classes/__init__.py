"""Multiaxis geometry-transform class plugins (option 116), one module per class (manual §4.2)."""
