"""Spindle-type plugins (option 19), one module per type (manual §4.5)."""
