"""gecent kernel: the CL reader, machine model, dispatcher and output stages.

The kernel flows one way (reader -> records -> macro layer -> dispatcher ->
motion/feed/spindle -> blocks -> formatting -> tape/listing); plugins hang off
the hook specifications in :mod:`gecent.core.hookspecs`.
"""

__version__ = "0.1.0"
