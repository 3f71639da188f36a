"""`python -m arnoldweb ...` runs the arnoldweb command installed with the package (same as `arnoldweb ...`)."""
from ._cli import main

main()
