"""Built-in gecent plugins, each registered through its own ``gecent`` entry point."""
