"""Callbacks shared by the counter nodes (a mixin in another module)."""


class ResetHandlers:
    def on_reset(self, request, response):  # ROS103
        self.count = 0
        if request.data:
            response.success = True
            return response

    def on_reset_checked(self, request, response):
        self.count = 0
        response.success = True
        return response

    def on_reset_delegated(self, request, response):
        return self.on_reset_checked(request, response)

    def on_tick(self, msg):
        self.count += 1

    def on_tick_with_default(self, event=None):
        self.count += 1

    def on_message(self, msg, topic='count'):
        self.last = (topic, msg)

    def on_anything(self, *args):
        self.last = args

    @staticmethod
    def log_result(future):
        print(future.result())


def on_topic(node, topic, msg):
    node.last = (topic, msg)


def log_reset(node, request, response):
    node.get_logger().info(f'reset: {request.data} -> {response.success}')
