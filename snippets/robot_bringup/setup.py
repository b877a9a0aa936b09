import os
from glob import glob

from setuptools import setup

package_name = 'robot_bringup'

setup(
    name=package_name,
    version='0.1.0',
    # [START no_code]
    packages=[],  # a bringup package owns no Python code: no module, no executable
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'),
         glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
        (os.path.join('share', package_name, 'config'),
         glob(os.path.join('config', '*.yaml'))),
    ],
    # [END no_code]
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description="How the book's robot is started: launch and parameter files only.",
    license='Apache-2.0',
)
