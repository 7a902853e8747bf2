"""Helpers shared by the nodes of this package."""
from nav_msgs.srv import GetMap


def fetch_map(client):
    request = GetMap.Request()
    return client.call(request)


def refresh(node):
    return fetch_map(node.map_client)
