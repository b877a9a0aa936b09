import os
from glob import glob

from setuptools import setup

package_name = 'capstone_bringup'

setup(
    name=package_name,
    version='0.1.0',
    packages=[],  # owns no code: launch and parameter files only
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
        (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
        (os.path.join('share', package_name, 'specs'), glob('specs/*.spec.yaml')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description='Launch and parameter files of the capstone robot system (chapter 7).',
    license='Apache-2.0',
    # colcon test runs pytest for a package whose 'test' extra names it (a
    # tests_require is ignored by newer setuptools, and colcon then runs unittest)
    extras_require={'test': ['pytest']},
)
