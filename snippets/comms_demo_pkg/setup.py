import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'comms_demo_pkg'

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
    description='A speed-limit server and a speed governor that never hears it, '
                'for the lesson on debugging communication with an assistant.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'limit_server = comms_demo_pkg.limit_server:main',
            'speed_governor = comms_demo_pkg.speed_governor:main',
        ],
    },
)
