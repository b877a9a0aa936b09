import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'tuning_demo_pkg'

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
    description='A camera and detector pipeline, configured wastefully on purpose, '
                'for the lesson on measuring and optimising node configuration.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'camera = tuning_demo_pkg.camera:main',
            'detector = tuning_demo_pkg.detector:main',
            'image_stats = tuning_demo_pkg.image_stats:main',
            'monitor = tuning_demo_pkg.monitor:main',
            'pipeline = tuning_demo_pkg.pipeline:main',
        ],
    },
)
