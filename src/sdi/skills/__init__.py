"""Skills (paper §III-B): tool-callable capabilities and the registry that dispatches them."""

from sdi.skills.builtin import default_registry
from sdi.skills.registry import SkillRegistry
from sdi.skills.skill import Skill, SkillResult

__all__ = ["Skill", "SkillRegistry", "SkillResult", "default_registry"]
