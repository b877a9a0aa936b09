import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'debug_demo_pkg'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'),
         glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description='A robot with four range sensors, broken on purpose in four ways, '
                'for the debugging lesson.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'range_sensor = debug_demo_pkg.range_sensor:main',
            'legacy_range_sensor = debug_demo_pkg.range_sensor:legacy_main',
            'obstacle_monitor = debug_demo_pkg.obstacle_monitor:main',
        ],
    },
)
