"""Posting many CL files at once (``gecent batch``, docs/batch.md)."""
