"""The camera and the detector in one process (one executor spins both)."""
from tuning_demo_pkg.camera import Camera
from tuning_demo_pkg.detector import Detector
from tuning_demo_pkg.spinning import run


def main():
    run(Camera, Detector)


if __name__ == '__main__':
    main()
