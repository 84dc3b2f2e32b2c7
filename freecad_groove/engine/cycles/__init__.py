"""The cycles of the engine, one module per cycle family.

Importing this package imports every module in it, and each cycle class
registers itself (``registry.register``): a new cycle is a new module here.
"""

import importlib
import pkgutil

for _module in pkgutil.iter_modules(__path__):
    if not _module.name.startswith("_"):
        importlib.import_module(__name__ + "." + _module.name)
