"""ACME VMC-1: an example third-party gecent machine pack."""
