import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'dock_watch_pkg'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'),
         glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
        (os.path.join('share', package_name, 'specs'), glob(os.path.join('specs', '*.yaml'))),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description='A battery simulator, a low-battery monitor and a dock planner, built from '
                'a written specification in the lesson on spec-driven systems.',
    license='Apache-2.0',
    # colcon test runs pytest for a package whose 'test' extra names it (a
    # tests_require is ignored by newer setuptools, and colcon then runs unittest)
    extras_require={'test': ['pytest']},
    entry_points={
        'console_scripts': [
            'battery_sim = dock_watch_pkg.battery_sim:main',
            'battery_monitor = dock_watch_pkg.battery_monitor:main',
            'dock_planner = dock_watch_pkg.dock_planner:main',
        ],
    },
)
