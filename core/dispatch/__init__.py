"""The dispatcher's side of the kernel: what statement handlers may use of a run."""
