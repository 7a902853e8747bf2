"""The security front end: SROS2 access-control policies (:mod:`.policy`)."""
