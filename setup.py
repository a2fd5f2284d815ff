"""The extension module of `pip install .` (pyproject.toml): the project's CMake build of the target
_cellproj, its cellproj libraries static, copied into the package."""
import glob
import os
import shutil
import subprocess

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.join(os.path.abspath(self.build_temp), "cmake")
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_SHARED_LIBS=OFF", "-DCELLPROJ_VTK=OFF"],
                       check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", build, "--target", "_cellproj", "-j", jobs], check=True)
        built = glob.glob(os.path.join(build, "python", "cellproj", "_cellproj*.so"))
        if len(built) != 1:
            raise RuntimeError("the CMake build made %d _cellproj modules in %s" % (len(built), build))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(built[0], target)


setup(ext_modules=[Extension("cellproj._cellproj", sources=[])], cmdclass={"build_ext": CMakeBuild})
