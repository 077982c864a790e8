"""Multihead processing (manual §3.4.8): the first pass keeps each head's command blocks in
its own scratch file; the merge pass GEMULT sequences them by OP/n and cuts both heads
together where the operation numbers agree."""
