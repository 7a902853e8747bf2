"""Hostile inputs: the analyser must survive anything a workspace can hold and still report the rest."""
