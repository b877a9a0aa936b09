import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'my_robot_pkg'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    # [START data_files]
    data_files=[
        # Register the package in the ament index so `ros2 run` and
        # `ros2 launch` can find it.
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # Install launch files and parameter files into share/my_robot_pkg/.
        # A file that is not listed here is not installed, and launch cannot find it.
        (os.path.join('share', package_name, 'launch'),
         glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
        (os.path.join('share', package_name, 'config'),
         glob(os.path.join('config', '*.yaml'))),
    ],
    # [END data_files]
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description='The example robot of the textbook: a range sensor, a filter '
                'and a configurable controller.',
    license='Apache-2.0',
    # [START entry_points]
    entry_points={
        'console_scripts': [
            # executable name = python module:function
            'sensor_publisher = my_robot_pkg.sensor_publisher:main',
            'data_processor = my_robot_pkg.data_processor:main',
            'robot_controller = my_robot_pkg.robot_controller:main',
            'print_counter = my_robot_pkg.print_counter:main',
        ],
    },
    # [END entry_points]
)
