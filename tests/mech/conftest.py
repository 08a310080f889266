"""The Jupyter kernel specs, installed once for the tests that start kernels (in a temporary
prefix that ``JUPYTER_PATH`` names, so the user's own Jupyter set-up is left alone)."""
import os

import pytest


@pytest.fixture(scope="session")
def kernel_specs(tmp_path_factory):
    from mech.kernelspec import install
    prefix = tmp_path_factory.mktemp("jupyter")
    saved = os.environ.get("JUPYTER_PATH")
    os.environ["JUPYTER_PATH"] = str(prefix / "share" / "jupyter")
    folders = install(prefix=str(prefix))
    yield folders
    if saved is None:
        del os.environ["JUPYTER_PATH"]
    else:
        os.environ["JUPYTER_PATH"] = saved
