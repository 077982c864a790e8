"""Positioning feed-type plugins (option 78), one module per type (manual §4.1.2)."""
