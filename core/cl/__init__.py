"""CL input: the record model, the vocabulary and the record stream (manual §3.3)."""
