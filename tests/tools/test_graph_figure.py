"""A drawn graph reaches the page as a captioned picture with alt text, at one scale."""
from __future__ import annotations

import base64
import io

from bs4 import BeautifulSoup
from labkit.drawing import DISPLAY_PX_PER_INCH, PNG_DPI, draw_graph
from labkit.graph import GraphSnapshot, Topic
from PIL import Image


def chain(*names: str) -> GraphSnapshot:
    """Nodes in a row, each publishing /<node>_out to the next one."""
    topics = {f'{a}_out': Topic(f'{a}_out', ('std_msgs/msg/Float32',), (a,), (b,))
              for a, b in zip(names, names[1:], strict=False)}
    return GraphSnapshot(tuple(sorted(names)), topics)


def rendered(figure) -> BeautifulSoup:
    data, metadata = figure._repr_mimebundle_()
    return BeautifulSoup(data['text/html'], 'html.parser'), data, metadata


def test_the_picture_carries_alt_text_listing_every_connection_and_a_caption():
    page, data, metadata = rendered(draw_graph(chain('/sensor', '/filter'), title='defaults'))
    image = page.select_one('figure.ros-graph > img')
    assert image['alt'] == ('ROS graph of 2 nodes: /filter, /sensor. '
                            'Topic /sensor_out is published by /sensor and read by /filter.')
    caption = page.select_one('figure.ros-graph > figcaption').text
    assert caption.startswith('The ROS graph, defaults: 2 nodes (ellipses) and 1 topic (boxes)')
    assert metadata['image/png']['alt'] == image['alt']
    assert data['text/plain'] == f'<ROS graph: {caption}>'


def test_a_given_caption_replaces_the_default():
    page, _, _ = rendered(draw_graph(chain('/a', '/b'), caption='Only the sensor runs.'))
    assert page.figcaption.text == 'Only the sensor runs.'


def test_every_graph_is_shown_at_the_same_scale():
    small = draw_graph(chain('/a', '/b'))
    wide = draw_graph(chain(*(f'/stage_{i}' for i in range(6))), title='a long title')
    for figure in (small, wide):
        page, _, _ = rendered(figure)
        image = page.select_one('img')
        png = Image.open(io.BytesIO(base64.b64decode(image['src'].split(',', 1)[1])))
        assert abs(png.width - figure.get_figwidth() * PNG_DPI) <= 1  # whole pixels
        assert int(image['width']) == round(figure.get_figwidth() * DISPLAY_PX_PER_INCH)
    assert wide.get_figwidth() > small.get_figwidth()


def test_an_empty_graph_still_says_what_it_shows():
    page, _, _ = rendered(draw_graph(GraphSnapshot((), {})))
    assert page.img['alt'] == 'ROS graph with no nodes.'
    assert '0 nodes' in page.figcaption.text
