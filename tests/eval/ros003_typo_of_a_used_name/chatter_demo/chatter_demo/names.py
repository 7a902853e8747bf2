"""Topic names shared by the demo's nodes."""
CHATTER = 'chatter'
RELAYED = 'chatter_relayed'
