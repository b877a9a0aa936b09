import os
from glob import glob

from setuptools import setup

package_name = 'rover_config'

setup(
    name=package_name,
    version='0.1.0',
    packages=[],  # configuration only: the nodes are my_robot_pkg's
    # [START data_files]
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'),
         glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
        # One entry per folder: glob('config/*.yaml') does not descend into
        # config/robots/ or config/sites/, and a file not listed is not installed.
        (os.path.join('share', package_name, 'config'),
         glob(os.path.join('config', '*.yaml'))),
        (os.path.join('share', package_name, 'config', 'robots'),
         glob(os.path.join('config', 'robots', '*.yaml'))),
        (os.path.join('share', package_name, 'config', 'sites'),
         glob(os.path.join('config', 'sites', '*.yaml'))),
    ],
    # [END data_files]
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description="Configuration of the book's rover: layered parameter files and the "
                'launch files that pick them.',
    license='Apache-2.0',
)
